// The opening break: the cue ball behind the head string, a hard hit on the apex ball, chosen
// from breaks measured over seeded hand racks.
#pragma once

#include <span>

#include "client/bot/ai/plan_context.h"
#include "rules/game_rules.h"

namespace pool::bot {

/// A break, mirrored for either side of the table.
struct BreakStroke {
  double y = 0.0;       ///< the cue ball's distance from the long string, m (on the head string)
  double offset = 0.0;  ///< aim point off the apex ball's centre, fraction of R (+: toward the
                        ///< cue ball's side of the long string)
  double speed = 9.0;   ///< ball speed, m/s
  double tip = 0.0;     ///< tip height, fraction of R
};

/// The breaks the bot plays in `game`, best first: the best of a grid of positions, aims, speeds
/// and tips by how often each keeps the turn over 200 seeded hand racks under the olympiad noise
/// (bot_bench's BreakGrid prints that grid; the figures are in break_shot.cpp).
std::span<const BreakStroke> measuredBreaks(rules::Game game);

/// `plan` played from `side` (+1: the +y half, −1: the −y half) at the object ball `apex`, on
/// the table of `view`. The cue ball sits 1 cm behind the head string.
PlannedShot breakShot(const TableView& view, const Vec2& apex, const BreakStroke& plan, int side);

/// True when the object balls on the table lie as a rack: at least nine of them, every one inside
/// the footprint of a five-row rack on the foot spot (with 3 mm to spare). A practice
/// table's fresh rack is such a table: the advice for it is a break.
bool looksRacked(const TableView& view, const std::vector<physics::Ball>& balls);

/// The object ball nearest the foot spot: the apex of the rack.
Vec2 apexBall(const TableView& view, const std::vector<physics::Ball>& balls);

/// The first measured break (each side in turn) whose stroke, tried in the physics, is legal and
/// keeps the cue ball on the table; the best-valued one tried when none is. A level that samples
/// its noise plays each legal one that way instead (up to 16 times) and takes the one worth most
/// on average: the turn kept with its leave, as a pot is worth (bot_bench, pro, 8-ball, 300
/// racks: break-and-runs 9 % -> 18 %). Always returns a shot.
PlannedShot planBreak(PlanContext& context);

}  // namespace pool::bot
