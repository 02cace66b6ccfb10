// Physics trial runs of planned shots, judged by the 8-ball rules.
#include "client/bot/ai/shot_verifier.h"

#include <algorithm>

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
  judged_shot.before =
      shot.cue_ball_at ? withCueBallAt(balls, *shot.cue_ball_at, view_.radius()) : balls;
  judged_shot.intent = intentOf(shot);
  // Only balls on the table go into the world; the rest stay where they are.
  std::vector<physics::Ball> in_play, down;
  for (const auto& b : judged_shot.before)
    (physics::onTable(b.state) ? in_play : down).push_back(b);
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
  std::vector<physics::Ball> left_on_table;
  for (const auto& b : trial.after) {
    if (physics::onTable(b.state)) left_on_table.push_back(b);
  }
  trial.dead_layout = !physics::checkPlacement(left_on_table, view_.geometry, view_.spec.params);
  for (const auto& b : trial.after) {
    if (b.id == physics::kCueBall && physics::onTable(b.state)) trial.cue_end = b.pos.head<2>();
  }
  return trial;
}

}  // namespace pool::bot
