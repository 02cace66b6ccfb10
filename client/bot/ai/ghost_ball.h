// Ghost-ball geometry: where the cue ball must touch an object ball to send it to a pocket, how
// thin the cut is, and whether the straight paths are free of other balls.
#pragma once

#include <optional>
#include <vector>

#include "client/bot/ai/table_view.h"
#include "physics/ball.h"
#include "table/physics_params.h"

namespace pool::bot {

/// One way to pot one ball: the cue ball rolls straight to the ghost-ball point, the object ball
/// goes straight to the pocket. Table frame, metres, radians.
struct PotLine {
  int ball = 0;                  ///< object ball id
  int pocket = -1;               ///< index into TableView::pockets
  Vec2 cue;                      ///< cue ball centre
  Vec2 object;                   ///< object ball centre
  Vec2 target;                   ///< where the object ball is sent (the pocket mouth)
  Vec2 ghost;                    ///< cue ball centre at contact
  double yaw = 0.0;              ///< heading of the cue ball, rad (0 = +x)
  double cut = 0.0;              ///< angle between the cue ball's path and the object ball's, rad
  double cue_distance = 0.0;     ///< cue ball centre to ghost point, m
  double object_distance = 0.0;  ///< object ball centre to target, m
  double difficulty = 0.0;       ///< larger is harder (dimensionless, for ranking only)
};

/// Largest cut the bot tries, rad.
inline constexpr double kMaxCut = 1.35;

/// The pot line of ball `id` at `object` into pocket `pocket` from a cue ball at `cue`, or empty
/// when the cut is too thin, the pocket cannot be entered from that side, or the ghost point is
/// off the playing surface. Other balls are not looked at (see pathClear).
std::optional<PotLine> potLine(const Vec2& cue, const Vec2& object, int id, int pocket,
                               const TableView& view);

/// Completes `line` (its cue, object and object_distance set) for an object ball sent from
/// `line.object` along the unit `direction`: the ghost point, the cut, the yaw and the difficulty.
/// False when the ghost point is off the playing surface or the cut is thinner than kMaxCut.
bool aimLine(PotLine& line, const Vec2& direction, const TableView& view);

/// The unit direction an object ball at `object` is sent in by a cue ball rolling straight from
/// `cue` along `yaw`: their line of centres at contact (what the ghost ball assumes: no throw).
/// Empty when the cue ball passes it by.
std::optional<Vec2> contactLine(const Vec2& cue, const Vec2& object, double yaw, double radius);

/// True when a ball of the view's radius moving straight from `from` to `to` touches none of the
/// balls on the table in `balls` other than `ignore_a` and `ignore_b` (ids; -1 for none).
bool pathClear(const Vec2& from, const Vec2& to, const std::vector<physics::Ball>& balls,
               double radius, int ignore_a, int ignore_b = -1);

/// Every pot line from the cue ball at `cue` on the balls `legal` (ids) into every pocket whose
/// two paths are clear, easiest first.
std::vector<PotLine> potLines(const Vec2& cue, const std::vector<physics::Ball>& balls,
                              const std::vector<int>& legal, const TableView& view);

/// The cue ball's speed just after the strike (m/s) that sends the object ball of `line` to the
/// pocket with some pace left, from the cloth's rolling resistance and a sliding start.
double potSpeed(const PotLine& line, const table::PhysicsParams& params);

/// The heading of `v` in the table plane, rad (0 = +x).
double angleOf(const Vec2& v);

/// `a` − `b` (rad) wrapped into [−π, π].
double angleBetween(double a, double b);

/// The centre of ball `id` in the table plane, if it is on the table in `balls`.
std::optional<Vec2> ballAt(const std::vector<physics::Ball>& balls, int id);

}  // namespace pool::bot
