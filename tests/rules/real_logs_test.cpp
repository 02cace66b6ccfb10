// The referee fed with real event logs from the physics engine: a legal break, a scratch, a
// pocketed 8.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "rules/eight_ball.h"
#include "rules/fixture.h"
#include "rules/real_play.h"
#include "rules/shot_facts.h"
#include "scenario/scenario.h"

namespace pool::rules {
namespace {

using test::parsed;
using test::play;
using test::Played;

Verdict judgedReal(const GameState& state, const Played& played) {
  auto verdict = judgeEightBall(state, played.shot, played.table);
  EXPECT_TRUE(verdict) << verdict.error();
  return verdict ? *verdict : Verdict{};
}

TEST(RealLogs, LegalBreak) {
  auto scene = scenario::loadScenario("break");
  ASSERT_TRUE(scene) << scene.error();
  // The scene puts the cue ball on the head spot, which lies on the head string; the break is
  // taken from behind it, so move the cue ball back a centimetre (the aim along +x is unchanged).
  // A little draw keeps the cue ball out of the pockets on this rack.
  for (auto& b : scene->balls) {
    if (b.id == 0) b.pos.x() -= 0.01;
  }
  scene->shot.tip_height = -0.2;
  Played played = play(*scene, Intent::none());
  auto facts = distilShot(played.shot, played.table.spots.head_string_x);
  ASSERT_TRUE(facts) << facts.error();
  EXPECT_TRUE(facts->cushioned.size() >= 4 || !facts->objectBallsPocketed().empty());

  Verdict v = judgedReal(newRack(0), played);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_FALSE(v.game_over);
  EXPECT_EQ(v.next.groups[0], Group::None);
  if (v.legal() && v.options.empty()) {
    EXPECT_EQ(v.turn_continues, !v.pocketed.empty()) << describe(v);
  }
}

TEST(RealLogs, ScratchIntoACornerPocket) {
  // The cue ball on the diagonal of the foot right corner pocket, shot straight into it.
  Played played = play(parsed(R"({
    "table": "wpa-9ft",
    "balls": [ {"id": 0, "x": 0.9, "y": -0.265}, {"id": 3, "x": -0.3, "y": 0.3},
               {"id": 8, "x": 0.0, "y": 0.3}, {"id": 12, "x": 0.3, "y": 0.3} ],
    "shot": {"yaw_deg": -45.0, "tip_side": 0.0, "tip_height": 0.0, "elevation_deg": 0.0,
             "speed": 1.5, "speed_is": "cue"}
  })"),
                       Intent::call(3, "head_left_corner"));
  Verdict v = judgedReal(test::assigned(), played);
  EXPECT_TRUE(v.hasFoul(Foul::CueBallPocketed)) << describe(v);
  EXPECT_TRUE(v.hasFoul(Foul::NoBallHit)) << describe(v);
  EXPECT_FALSE(v.game_over);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(RealLogs, EightPocketedInTheCalledPocket) {
  // Seat 0 has cleared the solids; the 8 sits on the diagonal of the foot right corner pocket and
  // the cue ball straight behind it; a draw stroke keeps the cue ball out of the pocket.
  Played played = play(parsed(R"({
    "table": "wpa-9ft",
    "balls": [ {"id": 0, "x": 0.6879, "y": -0.0529}, {"id": 8, "x": 0.9, "y": -0.265},
               {"id": 10, "x": -0.6, "y": 0.4}, {"id": 13, "x": -0.9, "y": -0.3} ],
    "shot": {"yaw_deg": -45.0, "tip_side": 0.0, "tip_height": -0.4, "elevation_deg": 0.0,
             "speed": 1.5, "speed_is": "cue"}
  })"),
                       Intent::call(8, "foot_right_corner"));
  Verdict v = judgedReal(test::assigned(), played);
  EXPECT_TRUE(v.game_over) << describe(v);
  EXPECT_EQ(v.end, GameEnd::EightPocketed) << describe(v);
  EXPECT_EQ(v.winner, 0);
  EXPECT_EQ(v.pocketed, std::vector<int>{8});
}

// The physics and the referee agree on what a consistent log is: no shipped scene, and no break
// of a few racks, is refused as contradictory.
TEST(RealLogs, ShippedScenesAndBreaksPassTheLogCheck) {
  std::filesystem::path scenes = std::filesystem::path(POOL_SOURCE_DIR) / "assets" / "scenes";
  for (const auto& entry : std::filesystem::directory_iterator(scenes)) {
    if (entry.path().extension() != ".json") continue;
    auto scene = scenario::loadScenario(entry.path().string());
    ASSERT_TRUE(scene) << entry.path() << ": " << scene.error();
    Played played = play(*scene, Intent::none());
    auto facts = distilShot(played.shot, played.table.spots.head_string_x);
    EXPECT_TRUE(facts) << entry.path().filename() << ": " << facts.error();
  }
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    auto scene = parsed(R"({"table": "wpa-9ft", "rack": "8ball", "seed": )" + std::to_string(seed) +
                        R"(, "balls": [{"id": 0, "x": -0.7, "y": 0.1}],
                        "shot": {"yaw_deg": -1.0, "speed": 9.0}})");
    Played played = play(scene, Intent::none());
    auto verdict = judgeEightBall(newRack(0), played.shot, played.table);
    EXPECT_TRUE(verdict) << "seed " << seed << ": " << verdict.error();
  }
}

}  // namespace
}  // namespace pool::rules
