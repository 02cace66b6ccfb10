// The mixer: a break's real event log never reaches full scale, voices are limited and stolen
// quietest-first, and mixing allocates nothing.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdlib>
#include <new>

#include "audio/shots.h"
#include "client/audio/mixer.h"
#include "client/audio/offline_render.h"
#include "client/audio/sound_cue.h"

// Counts every allocation of this test program, to show that mixing makes none. (GCC sees the
// malloc/free pair through inlining and wrongly calls it a new/delete mismatch.)
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
namespace {
std::atomic<long> g_allocations{0};
}  // namespace

void* operator new(std::size_t n) {
  ++g_allocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void* operator new[](std::size_t n) {
  return ::operator new(n);
}
// The nothrow forms too (std::stable_sort's buffer uses them): under AddressSanitizer they would
// otherwise come from its own allocator and be freed here with free().
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  ++g_allocations;
  return std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t& tag) noexcept {
  return ::operator new(n, tag);
}
void operator delete(void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete[](void* p, const std::nothrow_t&) noexcept {
  std::free(p);
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete[](void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}
void operator delete[](void* p, std::size_t) noexcept {
  std::free(p);
}

namespace pool::audio {
namespace {

TEST(Mixer, ABreaksEventLogStaysUnderFullScale) {
  const auto& events = test::breakEvents();
  const auto cues = cuesFromEvents(events, ImpactLaws{});
  ASSERT_GT(cues.size(), 50u) << "the break should sound a lot of impacts";
  MixerOptions options;
  const auto mixed = renderCues(cues, SoundBank{}, options);
  // Without the limiter the sum would pass full scale: the test is not vacuous.
  EXPECT_GT(mixed.stats.peak_in, 1.0f);
  EXPECT_GT(mixed.stats.limited, 0u);
  float peak = 0.0f;
  for (float s : mixed.samples) peak = std::max(peak, std::fabs(s));
  EXPECT_LT(peak, 1.0f);
  EXPECT_EQ(peak, mixed.stats.peak_out);
  EXPECT_LE(mixed.stats.max_active, options.voices);
  EXPECT_EQ(mixed.stats.started + mixed.stats.dropped, cues.size());
  EXPECT_GT(test::rms(mixed.samples), 0.005);
}

TEST(Mixer, AFullMixerStealsTheQuietestVoiceOrDropsAQuieterSound) {
  MixerOptions options;
  options.voices = 2;
  Mixer mixer(options);
  const std::vector<float> one(1000, 1.0f);
  mixer.start(one, 0.1f);
  mixer.start(one, 0.3f);
  mixer.start(one, 0.05f);  // quieter than both: dropped
  EXPECT_EQ(mixer.stats().dropped, 1u);
  mixer.start(one, 0.2f);  // takes the 0.1 voice
  EXPECT_EQ(mixer.stats().stolen, 1u);
  EXPECT_EQ(mixer.active(), 2);
  std::vector<float> out(10);
  mixer.mix(out);
  EXPECT_NEAR(out[0], 0.5f, 1e-6f);  // 0.3 + 0.2, under the clipper's knee
}

TEST(Mixer, DelaysPlaceSoundsAtTheirSampleAndVoicesEnd) {
  Mixer mixer;
  const std::vector<float> three(3, 0.5f);
  mixer.start(three, 1.0f, 5);
  std::vector<float> out(4);
  mixer.mix(out);  // frames 0-3: still waiting
  for (float s : out) EXPECT_EQ(s, 0.0f);
  mixer.mix(out);  // frames 4-7: the sound at 5, 6, 7
  EXPECT_EQ(out[0], 0.0f);
  EXPECT_FLOAT_EQ(out[1], 0.5f);
  EXPECT_FLOAT_EQ(out[3], 0.5f);
  EXPECT_EQ(mixer.active(), 0);
}

TEST(Mixer, TheSoftClipperIsLinearUnderTheKneeAndNeverReachesOne) {
  EXPECT_EQ(softClip(0.5f, 0.7f), 0.5f);
  EXPECT_EQ(softClip(-0.7f, 0.7f), -0.7f);
  EXPECT_GT(softClip(0.9f, 0.7f), 0.7f);
  EXPECT_LT(softClip(0.9f, 0.7f), 0.9f);
  EXPECT_LT(softClip(1e9f, 0.7f), 1.0f);
  EXPECT_GT(softClip(-1e9f, 0.7f), -1.0f);
  EXPECT_LT(softClip(0.8f, 0.7f), softClip(0.9f, 0.7f));
}

TEST(Mixer, StartingAndMixingAllocateNothing) {
  const SoundBank bank;
  const auto cues = cuesFromEvents(test::breakEvents(), ImpactLaws{});
  Mixer mixer;
  std::vector<float> block(512);
  const long before = g_allocations.load();
  for (const auto& cue : cues) {
    mixer.start(bank.pick(cue), static_cast<float>(cue.amplitude), 7);
    mixer.mix(block);
  }
  EXPECT_EQ(g_allocations.load(), before);
  EXPECT_GT(mixer.stats().started, 50u);
}

}  // namespace
}  // namespace pool::audio
