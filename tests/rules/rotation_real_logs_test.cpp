// The 9-ball and 10-ball referee fed with real event logs from the physics engine: breaks legal
// and not, the rack ball on the break, the lowest ball first, a push-out, three fouls.
#include <gtest/gtest.h>

#include <string>

#include "rules/fixture.h"
#include "rules/real_play.h"
#include "rules/rotation.h"
#include "rules/shot_facts.h"

namespace pool::rules {
namespace {

using test::parsed;
using test::play;
using test::Played;

const RotationConfig kNine{Rotation::NineBall, 40};
const RotationConfig kTen{Rotation::TenBall, 40};

Verdict judgedReal(const GameState& state, const Played& played, const RotationConfig& config) {
  auto verdict = judgeRotation(state, played.shot, played.table, config);
  EXPECT_TRUE(verdict) << verdict.error();
  return verdict ? *verdict : Verdict{};
}

ShotFacts factsOf(const Played& played) {
  auto facts = distilShot(played.shot, played.table.spots.head_string_x);
  EXPECT_TRUE(facts) << facts.error();
  return facts ? *facts : ShotFacts{};
}

// A rack of `rack` ("9ball", "10ball") broken from behind the head string at `speed` m/s.
Played breakOf(const std::string& rack, std::uint64_t seed, double speed) {
  return play(parsed(R"({"table": "wpa-9ft", "rack": ")" + rack + R"(", "seed": )" +
                     std::to_string(seed) + R"(, "balls": [{"id": 0, "x": -0.75, "y": 0.02}],
                     "shot": {"yaw_deg": -0.9, "tip_height": -0.2, "speed": )" +
                     std::to_string(speed) + "}}"),
              Intent::none());
}

// A state after the break, the table open, `shooter` to shoot from where the cue ball lies.
GameState inPlay(int shooter) {
  GameState state = newRack(1 - shooter);
  state.phase = Phase::Open;
  state.shooter = shooter;
  state.ball_in_hand = BallInHand::None;
  return state;
}

// The cue ball sent softly toward the right rail, where no ball lies: it hits nothing.
const char* kMiss = R"({
  "table": "wpa-9ft",
  "balls": [ {"id": 0, "x": -0.3, "y": 0.0}, {"id": 1, "x": 0.3, "y": 0.4},
             {"id": 2, "x": 0.5, "y": 0.3}, {"id": 9, "x": 0.7, "y": 0.35} ],
  "shot": {"yaw_deg": -90.0, "speed": 0.8}
})";

TEST(RotationRealLogs, HardBreaksAreJudgedAsTheirFactsSay) {
  int legal = 0;
  for (const char* rack : {"9ball", "10ball"}) {
    const RotationConfig& config = std::string(rack) == "9ball" ? kNine : kTen;
    for (std::uint64_t seed = 1; seed <= 4; ++seed) {
      Played played = breakOf(rack, seed, 9.0);
      ShotFacts facts = factsOf(played);
      Verdict v = judgedReal(newRack(0), played, config);
      const bool open = !facts.objectBallsPocketed().empty() || facts.cushioned.size() >= 4;
      const bool clean =
          facts.first_contact == 1 && !facts.cueBallLost() && facts.objectBallsOffTable().empty();
      EXPECT_EQ(v.legal(), open && clean) << rack << " seed " << seed << ": " << describe(v);
      EXPECT_EQ(v.hasFoul(Foul::IllegalBreak), !open) << describe(v);
      legal += v.legal() ? 1 : 0;
      if (v.game_over) {
        EXPECT_EQ(config.game, Rotation::NineBall) << describe(v);
        EXPECT_TRUE(facts.isPocketed(9));
        continue;
      }
      if (v.legal()) {
        EXPECT_EQ(v.turn_continues, !v.pocketed.empty()) << describe(v);
        EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PushOut}));
      } else {
        EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere) << describe(v);
        EXPECT_EQ(v.next.fouls_in_row[0], 1);
      }
    }
  }
  EXPECT_GT(legal, 0);
}

TEST(RotationRealLogs, ASoftBreakIsIllegal) {
  Played nine = breakOf("9ball", 3, 0.9);
  ShotFacts facts = factsOf(nine);
  ASSERT_EQ(facts.first_contact, 1);
  ASSERT_TRUE(facts.objectBallsPocketed().empty());
  ASSERT_LT(facts.cushioned.size(), 4u);
  Verdict v = judgedReal(newRack(0), nine, kNine);
  EXPECT_EQ(v.fouls, std::vector<Foul>{Foul::IllegalBreak}) << describe(v);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PushOut}));

  Played ten = breakOf("10ball", 3, 0.9);
  Verdict t = judgedReal(newRack(0), ten, kTen);
  EXPECT_EQ(t.fouls, std::vector<Foul>{Foul::IllegalBreak}) << describe(t);
  EXPECT_EQ(t.options,
            (std::vector<Choice>{Choice::PlayOn, Choice::ReBreak, Choice::OpponentReBreaks}));
}

// The 1 driven straight into the rack ball, which runs along the same line into the foot right
// corner pocket.
std::string rackBallCombo(int rack_ball) {
  return R"({
    "table": "wpa-9ft",
    "balls": [ {"id": 0, "x": -0.70, "y": 0.0}, {"id": 1, "x": 0.60, "y": -0.30},
               {"id": )" +
         std::to_string(rack_ball) + R"(, "x": 0.6514, "y": -0.3257},
               {"id": 2, "x": 0.2, "y": 0.4}, {"id": 3, "x": 0.4, "y": 0.45} ],
    "shot": {"yaw_deg": -12.39, "speed": 4.0}
  })";
}

TEST(RotationRealLogs, TheNineOnTheBreakWins) {
  Played played = play(parsed(rackBallCombo(9)), Intent::none());
  ShotFacts facts = factsOf(played);
  ASSERT_TRUE(facts.isPocketed(9));
  ASSERT_FALSE(facts.cueBallLost());
  Verdict v = judgedReal(newRack(0), played, kNine);
  EXPECT_TRUE(v.game_over) << describe(v);
  EXPECT_EQ(v.end, GameEnd::RackBallPocketed);
  EXPECT_EQ(v.winner, 0);
}

TEST(RotationRealLogs, TheTenOnTheBreakIsRespotted) {
  Played played = play(parsed(rackBallCombo(10)), Intent::none());
  ASSERT_TRUE(factsOf(played).isPocketed(10));
  Verdict v = judgedReal(newRack(0), played, kTen);
  EXPECT_FALSE(v.game_over) << describe(v);
  EXPECT_TRUE(v.legal());
  ASSERT_EQ(v.respots.size(), 1u);
  EXPECT_EQ(v.respots[0].id, 10);
  EXPECT_EQ(v.respots[0].pos, played.table.spots.foot_spot);
  EXPECT_TRUE(v.turn_continues);
}

TEST(RotationRealLogs, HittingTheThreeBeforeTheTwoIsAFoul) {
  Played played = play(parsed(R"({
    "table": "wpa-9ft",
    "balls": [ {"id": 0, "x": -0.3, "y": 0.0}, {"id": 3, "x": 0.3, "y": 0.0},
               {"id": 2, "x": 0.3, "y": 0.4}, {"id": 9, "x": 0.8, "y": -0.4} ],
    "shot": {"yaw_deg": 0.0, "speed": 2.0}
  })"),
                       Intent::none());
  ASSERT_EQ(factsOf(played).first_contact, 3);
  Verdict v = judgedReal(inPlay(0), played, kNine);
  EXPECT_TRUE(v.hasFoul(Foul::WrongBallFirst)) << describe(v);
  EXPECT_EQ(v.next_shooter, 1);
  EXPECT_EQ(v.ball_in_hand, BallInHand::Anywhere);
}

TEST(RotationRealLogs, APushOutMayMissEverything) {
  GameState after_break = inPlay(1);
  after_break.options = {Choice::PlayOn, Choice::PushOut};
  Intent push;
  push.choice = Choice::PushOut;
  Played pushed = play(parsed(kMiss), push);
  ASSERT_EQ(factsOf(pushed).first_contact, -1);
  Verdict v = judgedReal(after_break, pushed, kNine);
  EXPECT_TRUE(v.legal()) << describe(v);
  EXPECT_EQ(v.next_shooter, 0);
  EXPECT_EQ(v.options, (std::vector<Choice>{Choice::PlayOn, Choice::PassBack}));

  Intent play_on;
  play_on.choice = Choice::PlayOn;
  Verdict foul = judgedReal(after_break, play(parsed(kMiss), play_on), kNine);
  EXPECT_TRUE(foul.hasFoul(Foul::NoBallHit)) << describe(foul);
  EXPECT_EQ(foul.ball_in_hand, BallInHand::Anywhere);
}

TEST(RotationRealLogs, ThreeMissesInARowLoseTheRack) {
  GameState st = inPlay(0);
  Played miss = play(parsed(kMiss), Intent::safe());
  for (int round = 1; round <= 3; ++round) {
    Verdict v = judgedReal(st, miss, kTen);
    ASSERT_TRUE(v.hasFoul(Foul::NoBallHit)) << describe(v);
    if (round < 3) {
      EXPECT_FALSE(v.game_over) << describe(v);
      EXPECT_EQ(v.next.fouls_in_row[0], round);
      // The opponent shoots legally in between (the count is per player), then seat 0 again.
      st = v.next;
      st.shooter = 0;
      st.ball_in_hand = BallInHand::None;
    } else {
      EXPECT_TRUE(v.game_over);
      EXPECT_EQ(v.end, GameEnd::ThreeFouls);
      EXPECT_EQ(v.winner, 1);
    }
  }
}

}  // namespace
}  // namespace pool::rules
