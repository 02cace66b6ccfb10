// Events become cues: the right kind, nothing under the floor, loudness by the documented law.
#include <gtest/gtest.h>

#include <cmath>

#include "audio/shots.h"
#include "client/audio/offline_render.h"
#include "client/audio/sound_cue.h"

namespace pool::audio {
namespace {

using physics::EventType;
using test::event;

TEST(SoundCues, EachEventTypeMakesItsSoundOrNone) {
  const physics::EventLog log = {
      event(EventType::Strike, 0.0, 5.0, 0),   event(EventType::BallBall, 0.1, 2.0),
      event(EventType::BallCushion, 0.2, 1.0), event(EventType::Pocket, 0.3, 0.0),
      event(EventType::Land, 0.4, 1.0),        event(EventType::SlideToRoll, 0.5, 0.0),
      event(EventType::RollToRest, 0.6, 0.0),  event(EventType::Airborne, 0.7, 0.0),
      event(EventType::Respot, 0.8, 0.0)};
  const auto cues = cuesFromEvents(log, ImpactLaws{});
  ASSERT_EQ(cues.size(), 5u);
  EXPECT_EQ(cues[0].kind, SoundKind::CueStrike);
  EXPECT_EQ(cues[1].kind, SoundKind::BallClick);
  EXPECT_EQ(cues[2].kind, SoundKind::CushionThump);
  EXPECT_EQ(cues[3].kind, SoundKind::PocketDrop);
  EXPECT_EQ(cues[4].kind, SoundKind::CushionThump);
  EXPECT_DOUBLE_EQ(cues[1].amplitude, ImpactLaws{}.click.amplitude(2.0));
}

TEST(SoundCues, ImpactsUnderTheFloorAndBadTimesMakeNoSound) {
  const ImpactLaws laws;
  const physics::EventLog log = {event(EventType::BallBall, 0.1, laws.click.floor * 0.5),
                                 event(EventType::BallCushion, 0.2, laws.thump.floor * 0.9),
                                 event(EventType::BallBall, std::nan(""), 2.0),
                                 event(EventType::BallBall, 0.3, std::nan(""))};
  EXPECT_TRUE(cuesFromEvents(log, laws).empty());
  const auto mixed = renderCues(cuesFromEvents(log, laws), SoundBank{});
  EXPECT_EQ(test::rms(mixed.samples), 0.0);
}

TEST(SoundCues, CuesComeOutInTimeOrder) {
  const physics::EventLog log = {event(EventType::BallBall, 0.3, 2.0, 1),
                                 event(EventType::BallBall, 0.1, 2.0, 2),
                                 event(EventType::BallBall, 0.1, 2.0, 3)};
  const auto cues = cuesFromEvents(log, ImpactLaws{});
  ASSERT_EQ(cues.size(), 3u);
  EXPECT_EQ(cues[0].ball, 2);
  EXPECT_EQ(cues[1].ball, 3);
  EXPECT_EQ(cues[2].ball, 1);
}

/// RMS of one impact's sound, mixed alone.
double mixedRms(EventType type, double speed) {
  const auto cues = cuesFromEvents({event(type, 0.0, speed)}, ImpactLaws{});
  return test::rms(renderCues(cues, SoundBank{}, {}, 1.0).samples);
}

TEST(SoundCues, FasterImpactsAreLouderBySpeedToThePowerSixFifths) {
  const double law = std::pow(4.0, 1.2);  // amplitude ∝ speed^(6/5)
  EXPECT_NEAR(mixedRms(EventType::BallBall, 4.0) / mixedRms(EventType::BallBall, 1.0), law,
              0.02 * law);
  EXPECT_NEAR(mixedRms(EventType::BallCushion, 2.0) / mixedRms(EventType::BallCushion, 0.5), law,
              0.02 * law);
  const double strike = std::pow(2.0, 1.2);
  EXPECT_NEAR(mixedRms(EventType::Strike, 6.0) / mixedRms(EventType::Strike, 3.0), strike,
              0.02 * strike);
  // Past the cap nothing grows.
  EXPECT_NEAR(mixedRms(EventType::BallBall, 12.0) / mixedRms(EventType::BallBall, 8.0), 1.0, 0.05);
}

}  // namespace
}  // namespace pool::audio
