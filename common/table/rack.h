// Spots, strings and racks of a table (8-, 9- and 10-ball), shared by the physics lab, the rules
// and the server.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string_view>
#include <vector>

#include "table/table_spec.h"

namespace pool::table {

/// Marks on the table, table frame (origin at the centre, +x toward the foot).
struct Spots {
  Eigen::Vector2d head_spot;    ///< a quarter of the length from the head cushion
  Eigen::Vector2d foot_spot;    ///< a quarter of the length from the foot cushion
  Eigen::Vector2d centre_spot;  ///< the centre of the table
  double head_string_x =
      0.0;  ///< x of the head string (ball in hand after a break foul is at x < this)
};

Spots spotsFor(const TableSpec& spec);

enum class RackType { EightBall, NineBall, TenBall };
/// "8ball", "9ball", "10ball".
std::optional<RackType> rackTypeFromString(std::string_view name);

struct BallPlacement {
  int id = 0;
  Eigen::Vector2d pos;  ///< table plane, m
};

/// Object balls of a rack, apex on the foot spot, rows toward the foot cushion. 8-ball: the 8 in
/// the centre, one solid and one stripe in the back corners, the rest shuffled by `seed`. 9-ball:
/// a diamond, the 1 at the apex, the 9 in the centre, the rest by `seed`. 10-ball: a triangle of
/// four rows, the 1 at the apex, the 10 in the middle of the third row, the rest by `seed`.
/// Neighbours are `gap` metres apart (surface to surface). Deterministic for a seed.
std::vector<BallPlacement> rackBalls(RackType type, const TableSpec& spec, double ball_radius,
                                     std::uint64_t seed, double gap = 0.0);

/// Where a re-spotted ball goes: the foot spot, or the nearest free point behind it on the long
/// string (toward the foot cushion), then in front of it. `occupied` are the centres of the balls
/// on the table.
Eigen::Vector2d respotPosition(const TableSpec& spec, double ball_radius,
                               const std::vector<Eigen::Vector2d>& occupied);

}  // namespace pool::table
