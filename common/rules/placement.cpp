// Checks a ball's placement before a shot.
#include "rules/placement.h"

#include <cmath>

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
  }
  return "unknown";
}

std::string PlacementCheck::reason() const {
  switch (problem) {
    case PlacementProblem::None:
      return "";
    case PlacementProblem::NoBallInHand:
      return "the shooter does not have the cue ball in hand";
    case PlacementProblem::NotFinite:
      return "the position is not finite";
    case PlacementProblem::OffSlate:
      return "the ball would not lie on the slate";
    case PlacementProblem::OverPocket:
      return "the ball would be over a pocket";
    case PlacementProblem::Overlaps:
      return "the ball would overlap ball " + std::to_string(other);
    case PlacementProblem::NotBehindHeadString:
      return "the cue ball must be behind the head string";
  }
  return "unknown problem";
}

PlacementCheck checkBallPlacement(int id, const Eigen::Vector2d& pos,
                                  const std::vector<physics::Ball>& balls,
                                  const TableContext& table) {
  if (!pos.allFinite()) return {PlacementProblem::NotFinite};
  if (!onSlate(pos, table)) return {PlacementProblem::OffSlate};
  if (overPocket(pos, table)) return {PlacementProblem::OverPocket};
  if (int other = overlappedBall(id, pos, balls, table.ball_radius); other >= 0) {
    return {PlacementProblem::Overlaps, other};
  }
  return {};
}

PlacementCheck checkCueBallPlacement(BallInHand in_hand, const Eigen::Vector2d& pos,
                                     const std::vector<physics::Ball>& balls,
                                     const TableContext& table) {
  if (in_hand == BallInHand::None) return {PlacementProblem::NoBallInHand};
  PlacementCheck check = checkBallPlacement(physics::kCueBall, pos, balls, table);
  if (!check.ok()) return check;
  if (in_hand == BallInHand::BehindHeadString && !(pos.x() < table.spots.head_string_x)) {
    return {PlacementProblem::NotBehindHeadString};
  }
  return {};
}

Result<Eigen::Vector2d> placeCueBall(BallInHand in_hand, const Eigen::Vector2d& pos,
                                     const std::vector<physics::Ball>& balls,
                                     const TableContext& table) {
  PlacementCheck check = checkCueBallPlacement(in_hand, pos, balls, table);
  if (!check.ok()) return Result<Eigen::Vector2d>::fail(check.reason());
  return Result<Eigen::Vector2d>::ok(pos);
}

}  // namespace pool::rules
