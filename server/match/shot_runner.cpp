// One shot through the physics: on-table balls simulated, the rest carried over.
#include "server/match/shot_runner.h"

#include <algorithm>

namespace pool::server {

namespace {

void addBalls(std::vector<physics::Ball>& to, const std::vector<physics::Ball>& more) {
  to.insert(to.end(), more.begin(), more.end());
  std::sort(to.begin(), to.end(), [](const auto& a, const auto& b) { return a.id < b.id; });
}

}  // namespace

ShotRunner::ShotRunner(std::shared_ptr<const game::LoadedTable> kit)
    : kit_(std::move(kit)), simulation_(kit_->spec, kit_->geometry) {}

Result<physics::ShotOutcome> ShotRunner::run(const std::vector<physics::Ball>& balls,
                                             const physics::CueShot& cue, double sample_hz,
                                             double max_time) {
  using Out = Result<physics::ShotOutcome>;
  // Balls already down stay out of the world: the physics only moves what is on the table.
  std::vector<physics::Ball> in_play;
  std::vector<physics::Ball> down;
  for (const auto& b : balls) (physics::onTable(b.state) ? in_play : down).push_back(b);
  if (auto placed = simulation_.setBalls(in_play); !placed) return Out::fail(placed.error());
  auto outcome = simulation_.shoot(cue, physics::SimOptions{max_time, sample_hz});
  if (!outcome) return outcome;
  // Every ball of the match in every frame and at the end, in id order.
  addBalls(outcome->balls, down);
  for (auto& frame : outcome->trajectory) addBalls(frame.balls, down);
  return outcome;
}

}  // namespace pool::server
