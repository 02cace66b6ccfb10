// Checks a ball's placement before a shot.
#include "rules/placement.h"

#include <cmath>
#include <string>

namespace pool::rules {
namespace {

// Overlap tolerance: balls touching to within this distance are accepted (m).
constexpr double kTouchTolerance = 1e-9;

bool onSlate(const Eigen::Vector2d& pos, const TableContext& table) {
  double r = table.ball_radius;
  return std::abs(pos.x()) <= table.spec.length / 2 - r &&
         std::abs(pos.y()) <= table.spec.width / 2 - r;
}

bool overPocket(const Eigen::Vector2d& pos, const TableContext& table) {
  for (const auto& hole : table.holes) {
    if ((pos - hole.centre).norm() < hole.radius) return true;
  }
  return false;
}

int overlappedBall(int id, const Eigen::Vector2d& pos, const std::vector<physics::Ball>& balls,
                   double r) {
  for (const auto& b : balls) {
    if (b.id == id || !physics::onTable(b.state)) continue;
    if ((b.pos.head<2>() - pos).norm() < 2 * r - kTouchTolerance) return b.id;
  }
  return -1;
}

PlacementCheck refuse(PlacementProblem problem, std::string sentence) {
  return PlacementCheck::refuse(problem, std::move(sentence));
}

}  // namespace

const char* toString(PlacementProblem problem) {
  switch (problem) {
    case PlacementProblem::None:
      return "none";
    case PlacementProblem::NoBallInHand:
      return "no_ball_in_hand";
    case PlacementProblem::NotFinite:
      return "not_finite";
    case PlacementProblem::OffSlate:
      return "off_slate";
    case PlacementProblem::OverPocket:
      return "over_pocket";
    case PlacementProblem::Overlaps:
      return "overlaps";
    case PlacementProblem::NotBehindHeadString:
      return "not_behind_head_string";
    case PlacementProblem::NotInTheD:
      return "not_in_the_d";
  }
  return "unknown";
}

PlacementCheck checkBallPlacement(int id, const Eigen::Vector2d& pos,
                                  const std::vector<physics::Ball>& balls,
                                  const TableContext& table) {
  if (!pos.allFinite()) return refuse(PlacementProblem::NotFinite, "the position is not finite");
  if (!onSlate(pos, table))
    return refuse(PlacementProblem::OffSlate, "the ball would not lie on the slate");
  if (overPocket(pos, table))
    return refuse(PlacementProblem::OverPocket, "the ball would be over a pocket");
  if (int other = overlappedBall(id, pos, balls, table.ball_radius); other >= 0) {
    return refuse(PlacementProblem::Overlaps,
                  "the ball would overlap ball " + std::to_string(other));
  }
  return PlacementCheck::pass();
}

PlacementCheck checkCueBallPlacement(BallInHand in_hand, const Eigen::Vector2d& pos,
                                     const std::vector<physics::Ball>& balls,
                                     const TableContext& table) {
  if (in_hand == BallInHand::None) {
    return refuse(PlacementProblem::NoBallInHand, "the shooter does not have the cue ball in hand");
  }
  PlacementCheck check = checkBallPlacement(physics::kCueBall, pos, balls, table);
  if (!check.ok()) return check;
  if (in_hand == BallInHand::BehindHeadString && !(pos.x() < table.spots.head_string_x)) {
    return refuse(PlacementProblem::NotBehindHeadString,
                  "the cue ball must be behind the head string");
  }
  if (in_hand == BallInHand::InTheD && !(table.snooker && table::inTheD(*table.snooker, pos))) {
    return refuse(PlacementProblem::NotInTheD, "the cue ball must be in the D");
  }
  return PlacementCheck::pass();
}

Result<Eigen::Vector2d> placeCueBall(BallInHand in_hand, const Eigen::Vector2d& pos,
                                     const std::vector<physics::Ball>& balls,
                                     const TableContext& table) {
  PlacementCheck check = checkCueBallPlacement(in_hand, pos, balls, table);
  if (!check) return Result<Eigen::Vector2d>::fail(toString(check.code()), check.error());
  return Result<Eigen::Vector2d>::ok(pos);
}

}  // namespace pool::rules
