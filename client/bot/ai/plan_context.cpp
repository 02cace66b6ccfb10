// The planner's shared turn state and the layout evaluation used for position and safety play.
#include "client/bot/ai/plan_context.h"

#include "rules/game_rules.h"

namespace pool::bot {

std::optional<Trial> PlanContext::tryShot(const PlannedShot& shot) {
  if (runs_left <= 0) return std::nullopt;
  --runs_left;
  return verifier.run(balls, judge_state, shot);
}

std::optional<Vec2> PlanContext::probeHeading(const PlannedShot& shot, int id, double horizon) {
  if (runs_left <= 0) return std::nullopt;
  --runs_left;
  return verifier.heading(balls, shot, id, horizon);
}

std::optional<Trial> PlanContext::tryNoisy(const PlannedShot& shot) {
  PlannedShot played = shot;
  played.cue = perturbed(shot.cue, noise, rng);
  return tryShot(played);
}

std::optional<double> PlanContext::meanOfNoisy(const PlannedShot& shot, int tries,
                                               const std::function<double(const Trial&)>& worth) {
  double sum = 0.0;
  for (int k = 0; k < tries; ++k) {
    const auto trial = tryNoisy(shot);
    if (!trial) return std::nullopt;
    sum += worth(*trial);
  }
  return sum / tries;
}

double PlanContext::keptTurnWorth(const Trial& trial) const {
  const double sigma = noise.yaw > 0.0 ? noise.yaw : olympiadNoise(view.radius()).yaw;
  return 100.0 +
         leave_weight * leaveValue(trial.after, trial.verdict.next, view, sigma, look_ahead);
}

PlannedShot PlanContext::blank(ShotKind kind) const {
  PlannedShot shot;
  shot.kind = kind;
  shot.choice = choice;
  shot.calls_pockets = view.rules.game != rules::Game::Snooker;
  return shot;
}

std::vector<int> PlanContext::legalBalls() const {
  return rules::firstBallsFor(view.rules, play_state, balls);
}

std::vector<int> PlanContext::directBalls() const {
  auto ids = legalBalls();
  if (play_state.ball_in_hand != rules::BallInHand::BehindHeadString) return ids;
  std::erase_if(ids, [&](int id) {
    const auto at = ballAt(balls, id);
    return at && at->x() < view.headStringX();
  });
  return ids;
}

double shooterChances(const std::vector<physics::Ball>& balls, const rules::GameState& state,
                      const TableView& view) {
  if (state.phase == rules::Phase::Over) return 0.0;
  if (state.ball_in_hand != rules::BallInHand::None) return 1.0;
  const auto cue = ballAt(balls, physics::kCueBall);
  if (!cue) return 1.0;
  const auto lines = potLines(*cue, balls, rules::firstBallsFor(view.rules, state, balls), view);
  return lines.empty() ? 0.0 : 1.0 / (1.0 + lines.front().difficulty);
}

physics::CueShot stroke(double yaw, double speed, double tip) {
  physics::CueShot cue;
  cue.yaw = yaw;
  cue.speed = speed;
  cue.speed_is_ball = true;
  cue.tip_height = tip;
  return cue;
}

}  // namespace pool::bot
