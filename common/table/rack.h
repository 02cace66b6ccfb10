// Spots, strings and racks of a table (8-, 9-, 10-ball; three-cushion's opening; snooker's), shared
// by the physics lab, the rules and the server.
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

enum class RackType { EightBall, NineBall, TenBall, ThreeCushion, Snooker };
/// "8ball", "9ball", "10ball", "three_cushion", "snooker".
std::optional<RackType> rackTypeFromString(std::string_view name);

struct BallPlacement {
  int id = 0;
  Eigen::Vector2d pos;  ///< table plane, m
};

/// Object balls of a rack, apex on the foot spot, rows toward the foot cushion. 8-ball: the 8 in
/// the centre, one solid and one stripe in the back corners, the rest shuffled by `seed`. 9-ball:
/// a diamond, the 1 at the apex, the 9 in the centre, the rest by `seed`. 10-ball: a triangle of
/// four rows, the 1 at the apex, the 10 in the middle of the third row, the rest by `seed`.
/// Neighbours are `gap` metres apart (surface to surface). Three-cushion: the opening (see
/// caromOpening), the three balls, cue ball included. Snooker: see snookerRack (cue ball
/// included). Deterministic for a seed.
std::vector<BallPlacement> rackBalls(RackType type, const TableSpec& spec, double ball_radius,
                                     std::uint64_t seed, double gap = 0.0);

/// The breaker's ball beside the head spot on the head string, m (UMB: 182 mm to either side).
inline constexpr double kCaromBreakOffset = 0.182;

/// Three-cushion's opening position (UMB, World Rules of Carom Billiard, starting position): the
/// red (2) on the top spot (foot spot), the opponent's ball (1) on the bottom spot (head spot), the
/// breaker's ball (0) on the head string kCaromBreakOffset to one side of it, the side drawn from
/// `seed`.
std::vector<BallPlacement> caromOpening(const TableSpec& spec, std::uint64_t seed);

/// Snooker ball ids: 0 the cue ball, 1–15 the reds, then the colours in their order of value.
inline constexpr int kSnookerReds = 15;
inline constexpr int kSnookerYellow = 16;
inline constexpr int kSnookerGreen = 17;
inline constexpr int kSnookerBrown = 18;
inline constexpr int kSnookerBlue = 19;
inline constexpr int kSnookerPink = 20;
inline constexpr int kSnookerBlack = 21;

/// The gap between the pink and the apex red, m. Official Rules of Snooker, Section 2, "Position of
/// Balls": the apex red "as near to the pink as possible without touching it"; a millimetre is the
/// least a racking by hand reliably leaves.
inline constexpr double kSnookerApexGap = 1e-3;

/// Snooker's rack (Section 2, "Position of Balls"): the reds in a triangle of five rows, its apex
/// kSnookerApexGap behind the pink spot on the long string and its base toward the top cushion; the
/// colours on their spots; the cue ball in the D halfway between the brown and the yellow spots
/// (the breaker places it). Empty for a spec without snooker marks. Neighbouring reds are `gap`
/// apart.
std::vector<BallPlacement> snookerRack(const TableSpec& spec, double ball_radius, double gap = 0.0);

/// The spot of a snooker colour (16–21), for a spec with snooker marks.
std::optional<Eigen::Vector2d> snookerSpotOf(const TableSpec& spec, int colour);

/// How a match's racks are laid out; stored with each match, so that a stored match racks the
/// same after an upgrade that changes the generator.
enum class RackGenerator : int {
  Frozen = 0,  ///< every ball touching its neighbours (matches stored before racks had gaps)
  Hand = 1,    ///< small seeded gaps and offsets, as a racking with a triangle leaves
};
inline constexpr RackGenerator kCurrentRackGenerator = RackGenerator::Hand;
/// The generator stored as `value`; none for a value this program does not know.
std::optional<RackGenerator> rackGeneratorOf(std::int64_t value);

/// The most a hand-racked ball's centre strays from its slot in a frozen rack, m: the WPA's
/// tolerance on a ball's diameter, 2 1/4 in ± 0.005 in (WPA Equipment Specifications, "Balls"),
/// 0.127 mm. Balls of a set differ by up to twice that, so no triangle freezes them all; each
/// neighbour pair is 0 to 0.51 mm apart (its slots 0.254 mm apart, each ball within 0.127 mm).
inline constexpr double kRackStray = 0.127e-3;

/// The rack of `type` laid out by `generator`: Frozen is rackBalls with no gap; Hand puts the
/// slots 2 × kRackStray apart and moves each ball by up to kRackStray in a direction, both drawn
/// from `seed` (the same seed also chooses the order, as for Frozen); of a snooker rack only the
/// reds. No two balls overlap.
std::vector<BallPlacement> rackFor(RackType type, const TableSpec& spec, double ball_radius,
                                   std::uint64_t seed, RackGenerator generator);

/// Whether a ball at `p` would lie clear of every ball centred in `occupied` (none nearer than two
/// radii): where a re-spotted ball may go.
bool isFree(const Eigen::Vector2d& p, double ball_radius,
            const std::vector<Eigen::Vector2d>& occupied);

/// Where a re-spotted ball goes: the foot spot, or the nearest free point behind it on the long
/// string (toward the foot cushion), then in front of it. `occupied` are the centres of the balls
/// on the table.
Eigen::Vector2d respotPosition(const TableSpec& spec, double ball_radius,
                               const std::vector<Eigen::Vector2d>& occupied);

}  // namespace pool::table
