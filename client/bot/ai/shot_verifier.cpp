// Physics trial runs of planned shots, judged by the 8-ball rules.
#include "client/bot/ai/shot_verifier.h"

#include <algorithm>
#include <iterator>

#include "rules/eight_ball.h"

namespace pool::bot {
namespace {

// Far longer than any sensible shot; bounds a pathological one.
constexpr double kMaxShotTime = 40.0;

bool pocketedIn(const physics::EventLog& events, int id, const std::string& pocket) {
  return std::any_of(events.begin(), events.end(), [&](const physics::Event& e) {
    return e.type == physics::EventType::Pocket && e.ball_a == id && e.where == pocket;
  });
}

// The balls of `balls` on the table, in their order.
std::vector<physics::Ball> onTableOnly(const std::vector<physics::Ball>& balls) {
  std::vector<physics::Ball> out;
  std::copy_if(balls.begin(), balls.end(), std::back_inserter(out),
               [](const physics::Ball& b) { return physics::onTable(b.state); });
  return out;
}

// `balls` as `shot` is played from them: the cue ball placed first when it is in hand.
std::vector<physics::Ball> laidFor(const std::vector<physics::Ball>& balls, const PlannedShot& shot,
                                   double radius) {
  return shot.cue_ball_at ? withCueBallAt(balls, *shot.cue_ball_at, radius) : balls;
}

void sortById(std::vector<physics::Ball>& balls) {
  std::sort(balls.begin(), balls.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
}

}  // namespace

std::vector<physics::Ball> withCueBallAt(const std::vector<physics::Ball>& balls,
                                         const Eigen::Vector2d& at, double radius) {
  std::vector<physics::Ball> out;
  for (const auto& b : balls) {
    if (b.id != physics::kCueBall) out.push_back(b);
  }
  out.push_back(physics::restingBall(physics::kCueBall, at, radius));
  sortById(out);
  return out;
}

std::vector<physics::Ball> withRespots(std::vector<physics::Ball> balls,
                                       const rules::Verdict& verdict, double radius) {
  for (const auto& r : verdict.respots) {
    balls.erase(std::remove_if(balls.begin(), balls.end(),
                               [&](const physics::Ball& b) { return b.id == r.id; }),
                balls.end());
    balls.push_back(physics::restingBall(r.id, r.pos, radius));
  }
  sortById(balls);
  return balls;
}

ShotVerifier::ShotVerifier(const TableView& view)
    : view_(view), simulation_(view.spec, view.geometry) {}

Trial ShotVerifier::run(const std::vector<physics::Ball>& balls, const rules::GameState& state,
                        const PlannedShot& shot) {
  ++runs_;
  Trial trial;
  rules::Shot judged_shot;
  judged_shot.before = laidFor(balls, shot, view_.radius());
  judged_shot.intent = intentOf(shot);
  // Only balls on the table go into the world; the rest stay where they are.
  std::vector<physics::Ball> in_play, down;
  std::partition_copy(judged_shot.before.begin(), judged_shot.before.end(),
                      std::back_inserter(in_play), std::back_inserter(down),
                      [](const physics::Ball& b) { return physics::onTable(b.state); });
  if (auto placed = simulation_.setBalls(in_play); !placed) {
    trial.error = placed.error();
    return trial;
  }
  auto outcome = simulation_.shoot(shot.cue, physics::SimOptions{kMaxShotTime, 0.0});
  if (!outcome) {
    trial.error = outcome.error();
    return trial;
  }
  judged_shot.events = outcome->events;
  judged_shot.after = outcome->balls;
  judged_shot.after.insert(judged_shot.after.end(), down.begin(), down.end());
  sortById(judged_shot.after);
  auto verdict = rules::judgeShot(view_.rules, state, judged_shot, view_.context);
  if (!verdict) {
    trial.error = verdict.error();
    return trial;
  }
  trial.judged = true;
  trial.verdict = *verdict;
  trial.after = withRespots(judged_shot.after, trial.verdict, view_.radius());
  trial.potted_call =
      shot.called_ball && pocketedIn(outcome->events, *shot.called_ball, shot.called_pocket);
  trial.wins = trial.verdict.game_over && trial.verdict.winner == state.shooter;
  trial.loses = trial.verdict.game_over && trial.verdict.winner != state.shooter;
  trial.dead_layout =
      !physics::checkPlacement(onTableOnly(trial.after), view_.geometry, view_.spec.params);
  for (const auto& b : trial.after) {
    if (b.id == physics::kCueBall && physics::onTable(b.state)) trial.cue_end = b.pos.head<2>();
  }
  return trial;
}

std::optional<Eigen::Vector2d> ShotVerifier::heading(const std::vector<physics::Ball>& balls,
                                                     const PlannedShot& shot, int id,
                                                     double horizon) {
  ++runs_;
  const auto in_play = onTableOnly(laidFor(balls, shot, view_.radius()));
  const auto start = std::find_if(in_play.begin(), in_play.end(),
                                  [&](const physics::Ball& b) { return b.id == id; });
  if (start == in_play.end() || !simulation_.setBalls(in_play)) return std::nullopt;
  const auto outcome = simulation_.shoot(shot.cue, physics::SimOptions{horizon, 0.0});
  if (!outcome) return std::nullopt;
  const Eigen::Vector2d from = start->pos.head<2>();
  const auto away = [&](const Eigen::Vector2d& to) -> std::optional<Eigen::Vector2d> {
    constexpr double kMoved = 1e-3;  // m: less is no direction
    if ((to - from).norm() < kMoved) return std::nullopt;
    return (to - from).normalized();
  };
  bool struck = false;
  for (const auto& e : outcome->events) {
    if (e.type == physics::EventType::BallBall && !struck) {
      const bool cue_ball = e.ball_a == physics::kCueBall || e.ball_b == physics::kCueBall;
      const bool this_ball = e.ball_a == id || e.ball_b == id;
      if (cue_ball && !this_ball) return std::nullopt;  // the cue ball met another ball first
      struck = cue_ball && this_ball;
      continue;
    }
    if (!struck) continue;
    // Its first event after the strike (it starts to roll, meets a cushion or drops): the
    // straight path it left along.
    if (e.ball_a == id) return away(e.pos.head<2>());
    // Met by a ball of a lower id (named first), before an event of its own: its centre is not in
    // the event.
    if (e.ball_b == id) return std::nullopt;
  }
  if (!struck) return std::nullopt;
  for (const auto& b : outcome->balls) {
    if (b.id == id) return away(b.pos.head<2>());
  }
  return std::nullopt;
}

}  // namespace pool::bot
