// The bot's three-cushion search on the carom table, and its execution noise kept within the
// strokes the server takes.
#include <gtest/gtest.h>

#include <cmath>

#include "client/bot/ai/carom_search.h"
#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/table_view.h"
#include "physics/shot_limits.h"
#include "rules/game_rules.h"
#include "rules/three_cushion.h"
#include "table/rack.h"

namespace pool::bot {
namespace {

const TableView& caromView() {
  static const TableView view = [] {
    auto loaded = loadTableView("carom-match");
    EXPECT_TRUE(loaded) << loaded.error();
    TableView v = std::move(*loaded);
    v.rules.game = rules::Game::ThreeCushion;
    return v;
  }();
  return view;
}

std::vector<physics::Ball> opening(std::uint64_t seed) {
  std::vector<physics::Ball> balls;
  for (const auto& p : table::caromOpening(caromView().spec, seed)) {
    balls.push_back(physics::restingBall(p.id, p.pos, caromView().radius()));
  }
  return balls;
}

TEST(CaromSearch, TheOpeningStrokeScoresOffTheRedFirst) {
  // From the opening the search finds a point (a player's first stroke of a game, UMB: the red
  // first); played exactly it scores in the physics, judged by the rules.
  ShotVerifier verifier(caromView());
  const rules::GameState state = rules::newRackOf(rules::Game::ThreeCushion, 0);
  const auto balls = opening(1);
  const PlannedShot shot = planCarom(verifier, balls, state, {2000, {}, 0});
  EXPECT_EQ(shot.cue.ball, rules::kCaromWhite);
  EXPECT_EQ(shot.kind, ShotKind::Carom) << describe(shot);
  const Trial t = verifier.run(balls, state, shot);
  ASSERT_TRUE(t.judged) << t.error;
  EXPECT_TRUE(t.verdict.legal()) << rules::describe(t.verdict);
  EXPECT_EQ(t.verdict.scored, 1) << rules::describe(t.verdict);
}

TEST(CaromSearch, TheOtherPlayerStrikesTheYellow) {
  ShotVerifier verifier(caromView());
  rules::GameState state = rules::newRackOf(rules::Game::ThreeCushion, 0);
  state.phase = rules::Phase::Open;
  state.shooter = 1;
  const PlannedShot shot = planCarom(verifier, opening(2), state, {400, {}, 0});
  EXPECT_EQ(shot.cue.ball, rules::kCaromYellow);
}

TEST(ExecutionNoise, ATipPushedPastTheMiscueLimitLandsOnItsEdge) {
  // The server refuses a stroke beyond the miscue limit (physics/shot_limits.h): noise on a
  // stroke near it must not make one.
  physics::CueShot near;
  near.speed = 3.0;
  near.tip_side = 0.45;
  near.tip_height = 0.2;  // 0.49 R off centre
  ExecutionNoise noise;
  noise.tip = 0.05;
  Rng rng(5);
  int clamped = 0;
  for (int i = 0; i < 200; ++i) {
    const physics::CueShot out = perturbed(near, noise, rng);
    const double offset = std::hypot(out.tip_side, out.tip_height);
    EXPECT_LE(offset, physics::kMiscueLimit);
    clamped += offset > physics::kMiscueLimit * (1.0 - 1e-6) ? 1 : 0;
  }
  EXPECT_GT(clamped, 0);  // the noise did reach the limit: the clamp was exercised
}

}  // namespace
}  // namespace pool::bot
