// Two bots play whole racks offline (physics and rules in-process, no network): each rack ends
// with a winner in a bounded number of shots, every layout a shot leaves is one the physics
// accepts as the next shot's input, and skill noise does not stop that.
#include <gtest/gtest.h>

#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/skill_noise.h"
#include "physics/simulation.h"
#include "rules/eight_ball.h"
#include "support/ai_fixture.h"
#include "table/rack.h"

namespace pool::bot::test {
namespace {

std::vector<physics::Ball> freshRack(std::uint64_t seed) {
  const auto& view = nineFoot();
  std::vector<physics::Ball> balls{resting(0, view.context.spots.head_spot.x() - 0.01, 0.0)};
  for (const auto& p :
       table::rackBalls(table::RackType::EightBall, view.spec, view.radius(), seed)) {
    balls.push_back(resting(p.id, p.pos.x(), p.pos.y()));
  }
  std::sort(balls.begin(), balls.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
  return balls;
}

/// Where the layout a shot left would be refused as the next shot's input: the physics re-spots a
/// ball that comes to rest where its own placement check refuses it, so this must stay empty.
Check<> refusedLayout(const std::vector<physics::Ball>& balls) {
  const auto& view = nineFoot();
  return physics::checkPlacement(balls, view.geometry, view.spec.params);
}

struct RackOutcome {
  int winner = -1;
  int shots = 0;
  rules::GameEnd end = rules::GameEnd::None;
};

RackOutcome playRack(double skill, std::uint64_t seed) {
  const auto& view = nineFoot();
  ShotPlanner planner(view);
  ShotVerifier physics(view);
  SkillNoise noise(skill, seed);
  rules::GameState state = rules::newRack(0);
  auto balls = freshRack(seed);
  RackOutcome outcome;
  for (; outcome.shots < 150 && state.phase != rules::Phase::Over; ++outcome.shots) {
    PlannedShot shot = planner.plan(balls, state);
    if (!shoots(shot)) {
      auto verdict = rules::applyChoice(state, *shot.choice, balls, view.context);
      EXPECT_TRUE(verdict) << verdict.error();
      if (!verdict) break;
      if (verdict->rerack)
        balls = freshRack(seed + 1000 + static_cast<std::uint64_t>(outcome.shots));
      state = verdict->next;
      continue;
    }
    shot.cue = noise.apply(shot.cue);
    const Trial trial = physics.run(balls, state, shot);
    EXPECT_TRUE(trial.judged) << trial.error << " on " << describe(shot);
    if (!trial.judged) break;
    balls = trial.verdict.rerack
                ? freshRack(seed + 2000 + static_cast<std::uint64_t>(outcome.shots))
                : trial.after;
    const auto refused = refusedLayout(balls);
    EXPECT_TRUE(refused.ok()) << refused.error() << ": seed " << seed << ", shot " << outcome.shots
                              << " (" << describe(shot) << ") left a layout the physics refuses";
    if (!refused) break;
    state = trial.verdict.next;
  }
  outcome.winner = state.winner;
  outcome.end = state.end;
  return outcome;
}

TEST(SelfPlayTest, SkilledBotsFinishRacks) {
  for (std::uint64_t seed : {1u, 2u, 3u, 4u, 5u, 6u}) {
    const RackOutcome outcome = playRack(0.8, seed);
    EXPECT_GE(outcome.winner, 0) << "seed " << seed << ": no winner after " << outcome.shots;
    EXPECT_LT(outcome.shots, 150);
    std::printf("seed %llu: winner %d after %d shots (%s)\n", static_cast<unsigned long long>(seed),
                outcome.winner, outcome.shots, rules::toString(outcome.end));
  }
}

}  // namespace
}  // namespace pool::bot::test
