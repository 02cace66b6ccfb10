// The synthesised sounds: deterministic, normalised, finite, ending in silence, brighter when
// asked.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "audio/shots.h"
#include "client/audio/sound_bank.h"
#include "client/audio/synth.h"

namespace pool::audio {
namespace {

constexpr SoundKind kKinds[] = {SoundKind::CueStrike, SoundKind::BallClick, SoundKind::CushionThump,
                                SoundKind::PocketDrop};

/// Sign changes per second: a rough measure of where a sound's energy sits in frequency.
double crossingsPerSecond(const std::vector<float>& s, int rate) {
  int n = 0;
  for (std::size_t i = 1; i < s.size(); ++i) n += (s[i - 1] < 0.0f) != (s[i] < 0.0f);
  return n * static_cast<double>(rate) / static_cast<double>(s.size());
}

TEST(Synth, SameArgumentsGiveTheSameSamplesBitForBit) {
  for (SoundKind kind : kKinds) {
    const auto a = synthesize(kind, 1.1, 2);
    const auto b = synthesize(kind, 1.1, 2);
    ASSERT_EQ(a.size(), b.size()) << toString(kind);
    EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(float)), 0) << toString(kind);
  }
}

TEST(Synth, VariantsDiffer) {
  for (SoundKind kind : kKinds) {
    EXPECT_NE(synthesize(kind, 1.0, 0), synthesize(kind, 1.0, 1)) << toString(kind);
  }
}

TEST(Synth, SoundsHaveTheirLengthUnitRmsAndEndInSilence) {
  for (SoundKind kind : kKinds) {
    for (int rate : {44100, 48000}) {
      const auto s = synthesize(kind, 1.0, 0, rate);
      EXPECT_EQ(s.size(), static_cast<std::size_t>(soundLength(kind) * rate)) << toString(kind);
      for (float x : s) ASSERT_TRUE(std::isfinite(x)) << toString(kind);
      EXPECT_NEAR(test::rms(s), 1.0, 1e-3) << toString(kind);
      EXPECT_EQ(s.back(), 0.0f) << toString(kind);
    }
  }
}

TEST(Synth, TheThumpSitsBelowTheClickAndBrightnessRaisesTheClick) {
  const int rate = kDefaultSampleRate;
  const double click = crossingsPerSecond(synthesize(SoundKind::BallClick, 1.0, 0), rate);
  const double thump = crossingsPerSecond(synthesize(SoundKind::CushionThump, 1.0, 0), rate);
  EXPECT_GT(click, 4.0 * thump);
  const double dull = crossingsPerSecond(synthesize(SoundKind::BallClick, 0.7, 0), rate);
  const double bright = crossingsPerSecond(synthesize(SoundKind::BallClick, 1.4, 0), rate);
  EXPECT_GT(bright, 1.5 * dull);
}

TEST(Synth, TheClickDecaysQuicklyAndThePocketDropRollsOn) {
  // Energy in the second half of a click is a small fraction; a pocket drop's roll still sounds
  // half a second after the drop.
  const auto click = synthesize(SoundKind::BallClick, 1.0, 0);
  const std::vector<float> tail(click.begin() + static_cast<long>(click.size() / 2), click.end());
  EXPECT_LT(test::rms(tail), 0.05);
  const auto drop = synthesize(SoundKind::PocketDrop, 1.0, 0);
  const std::size_t at = static_cast<std::size_t>(0.5 * kDefaultSampleRate);
  const std::vector<float> roll(drop.begin() + static_cast<long>(at),
                                drop.begin() + static_cast<long>(at + 4800));
  EXPECT_GT(test::rms(roll), 0.1);
}

TEST(SoundBank, BandsSpanTheBrightnessRangeAndPickIsStable) {
  EXPECT_DOUBLE_EQ(SoundBank::bandBrightness(0), 0.7);
  EXPECT_NEAR(SoundBank::bandBrightness(SoundBank::kBands - 1), 1.4, 1e-12);
  EXPECT_EQ(SoundBank::bandOf(0.7), 0);
  EXPECT_EQ(SoundBank::bandOf(1.4), SoundBank::kBands - 1);
  EXPECT_EQ(SoundBank::bandOf(100.0), SoundBank::kBands - 1);
  EXPECT_EQ(SoundBank::bandOf(std::nan("")), 0);
  const SoundBank bank;
  const SoundCue cue{0.25, SoundKind::BallClick, 0.01, 1.0, 3};
  EXPECT_EQ(bank.pick(cue).data(), bank.pick(cue).data());
  const SoundCue drop{0.25, SoundKind::PocketDrop, 0.05, 1.4, 3};
  EXPECT_EQ(bank.pick(drop).size(), synthesize(SoundKind::PocketDrop, 1.0, 0).size());
}

}  // namespace
}  // namespace pool::audio
