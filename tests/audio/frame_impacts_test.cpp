// Impacts read off 60 Hz frames of real shots agree with the physics' own event log.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "audio/shots.h"
#include "client/audio/frame_impacts.h"
#include "table/table_spec.h"

namespace pool::audio {
namespace {

using physics::EventLog;
using physics::EventType;

constexpr double kFrame = 1.0 / 60.0;

/// A scene run with 60 Hz frames, and the events read off those frames.
struct FramedShot {
  physics::ShotOutcome outcome;
  EventLog inferred;
};

FramedShot frameShot(const std::string& scene) {
  FramedShot shot{test::framedShot(scene), {}};
  FrameImpacts impacts;
  for (const auto& frame : shot.outcome.trajectory) {
    const auto events = impacts.onFrame(frame.balls, frame.t);
    shot.inferred.insert(shot.inferred.end(), events.begin(), events.end());
  }
  return shot;
}

std::vector<physics::Event> ofType(const EventLog& log, EventType type) {
  std::vector<physics::Event> out;
  std::copy_if(log.begin(), log.end(), std::back_inserter(out),
               [&](const physics::Event& e) { return e.type == type; });
  return out;
}

TEST(FrameImpacts, AStraightPotReadsAsStrikeClickAndDropInTime) {
  const auto shot = frameShot("straight_pocket");
  const auto strikes = ofType(shot.inferred, EventType::Strike);
  const auto true_strike = ofType(shot.outcome.events, EventType::Strike);
  ASSERT_EQ(strikes.size(), 1u);
  ASSERT_EQ(true_strike.size(), 1u);
  EXPECT_EQ(strikes[0].t, 0.0);
  EXPECT_NEAR(strikes[0].speed, true_strike[0].speed, 0.05 * true_strike[0].speed);

  const auto clicks = ofType(shot.inferred, EventType::BallBall);
  const auto true_clicks = ofType(shot.outcome.events, EventType::BallBall);
  ASSERT_EQ(clicks.size(), 1u);
  ASSERT_EQ(true_clicks.size(), 1u);
  EXPECT_NEAR(clicks[0].t, true_clicks[0].t, kFrame);
  EXPECT_NEAR(clicks[0].speed, true_clicks[0].speed, 0.1 * true_clicks[0].speed);
  EXPECT_EQ(std::set<int>({clicks[0].ball_a, clicks[0].ball_b}), std::set<int>({0, 1}));

  const auto drops = ofType(shot.inferred, EventType::Pocket);
  const auto true_drops = ofType(shot.outcome.events, EventType::Pocket);
  ASSERT_EQ(drops.size(), 1u);
  ASSERT_EQ(true_drops.size(), 1u);
  EXPECT_EQ(drops[0].ball_a, 1);
  EXPECT_NEAR(drops[0].t, true_drops[0].t, kFrame);
}

TEST(FrameImpacts, ABreakReadsWithItsFirstClickAndEveryDrop) {
  const auto shot = frameShot("break");
  const auto clicks = ofType(shot.inferred, EventType::BallBall);
  const auto true_clicks = ofType(shot.outcome.events, EventType::BallBall);
  ASSERT_FALSE(clicks.empty());
  EXPECT_NEAR(clicks.front().t, true_clicks.front().t, kFrame);
  // Several contacts inside one frame cannot all be told apart, but most are heard, and the
  // rack's chains are not taken for cushions.
  EXPECT_GT(clicks.size(), true_clicks.size() / 2);
  const auto thumps = ofType(shot.inferred, EventType::BallCushion).size();
  const auto true_thumps = ofType(shot.outcome.events, EventType::BallCushion).size();
  EXPECT_GT(thumps, true_thumps / 2);
  EXPECT_LT(thumps, true_thumps * 3 / 2);
  std::multiset<int> dropped, true_dropped;
  for (const auto& e : ofType(shot.inferred, EventType::Pocket)) dropped.insert(e.ball_a);
  for (const auto& e : ofType(shot.outcome.events, EventType::Pocket))
    true_dropped.insert(e.ball_a);
  EXPECT_EQ(dropped, true_dropped);
  EXPECT_TRUE(std::is_sorted(shot.inferred.begin(), shot.inferred.end(),
                             [](const auto& a, const auto& b) { return a.t < b.t; }));
}

TEST(FrameImpacts, CushionsAreHeardInACushionShot) {
  const auto shot = frameShot("bank");
  EXPECT_EQ(ofType(shot.inferred, EventType::Pocket).size(), 1u);  // at rest: the final frame
  const auto thumps = ofType(shot.inferred, EventType::BallCushion);
  const auto true_thumps = ofType(shot.outcome.events, EventType::BallCushion);
  ASSERT_FALSE(true_thumps.empty());
  ASSERT_FALSE(thumps.empty());
  EXPECT_NEAR(thumps.front().t, true_thumps.front().t, kFrame);
  // The heard speed is the frame-to-frame |Δv| / (1 + 0.75) (FrameImpactOptions); the physics'
  // speed is the closing speed along the nose's normal, cos θ = 0.963 of the horizontal normal
  // speed v_n (nose at 1.27 R: sin θ = 0.27). Head-on, |Δv| is (1 + r) v_n with r the horizontal
  // rebound ratio, between 0.70 and e_c = 0.85 (0.80 for a rolling ball head-on, the published
  // Mathavan rebound of CushionMathavan; e_c the frictionless ceiling): 1.01–1.10 of the physics'
  // speed. The cloth's pull over one frame (u_s g / 60 = 0.033 m/s) and the small change along
  // the cushion add under 3 % of a 1.7 m/s impact either way: 0.98–1.13.
  const auto spec = table::loadTableSpec("wpa-9ft");  // the bank scene's table
  ASSERT_TRUE(spec) << spec.error();
  ASSERT_EQ(spec->params.e_c, 0.85);
  ASSERT_EQ(spec->params.u_s, 0.2);
  ASSERT_NEAR(spec->params.cushion_height, 1.27 * spec->params.ball_radius, 1e-9);
  const double heard = thumps.front().speed / true_thumps.front().speed;
  EXPECT_GT(heard, 0.98);
  EXPECT_LT(heard, 1.13);
}

TEST(FrameImpacts, ALateFirstFrameGivesNoStrikeAndOldFramesGiveNothing) {
  const auto shot = frameShot("straight_pocket");
  const auto& frames = shot.outcome.trajectory;
  ASSERT_GT(frames.size(), 30u);
  FrameImpacts late;
  EXPECT_TRUE(late.onFrame(frames[20].balls, frames[20].t).empty());
  EXPECT_TRUE(late.onFrame(frames[10].balls, frames[10].t).empty());  // out of order
  EXPECT_TRUE(late.onFrame(frames[20].balls, frames[20].t).empty());  // repeated
  FrameImpacts fresh;
  EXPECT_EQ(fresh.onFrame(frames[0].balls, frames[0].t).size(), 1u);
  fresh.reset();
  EXPECT_EQ(fresh.onFrame(frames[0].balls, frames[0].t).size(), 1u);
}

}  // namespace
}  // namespace pool::audio
