// Bank pots: the object ball sent off one cushion into a pocket, aimed at the pocket's mirror
// image in the line the ball's centre runs along that cushion.
#pragma once

#include <array>
#include <span>
#include <vector>

#include "client/bot/ai/ghost_ball.h"
#include "client/bot/ai/table_view.h"
#include "physics/ball.h"

namespace pool::bot {

/// How much harder a bank is ranked than a direct pot of the same length and cut.
inline constexpr double kBankDifficulty = 2.5;

/// Where along the cushion (m, from the mirror's bounce point) banks are aimed: a real cushion
/// sends a ball off shorter or longer than a mirror (its height, its grip, the ball's pace and
/// spin), so each bank is also tried a little to either side.
inline constexpr std::array<double, 5> kBankShifts{0.0, 0.03, -0.03, 0.06, -0.06};

/// Every one-cushion bank of the balls `legal` (ids) from a cue ball at `cue` whose three paths
/// (cue ball to the ghost point, object ball to the cushion, cushion to the pocket) are clear,
/// aimed at the mirror's bounce point moved along the cushion by each of `shifts`, easiest first.
/// Each line's `target` lies on the object ball's path beyond the cushion, as far from it as the
/// whole way the ball rolls (the pocket's mirror image when unshifted), so `object_distance` is
/// that way; a bounce within 12 cm of a pocket's opening, or off a cushion the pocket lies on, is
/// not tried. The physics trials judge what really drops.
std::vector<PotLine> bankLines(const Vec2& cue, const std::vector<physics::Ball>& balls,
                               const std::vector<int>& legal, const TableView& view,
                               std::span<const double> shifts = kBankShifts);

}  // namespace pool::bot
