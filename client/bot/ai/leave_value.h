// What a leave is worth to its shooter: the chance of a pot next, and, looking one shot further,
// of getting position on another ball after it.
#pragma once

#include <vector>

#include "client/bot/ai/ghost_ball.h"
#include "client/bot/ai/table_view.h"
#include "physics/ball.h"
#include "rules/game_state.h"

namespace pool::bot {

/// The chance a shooter with aim error `yaw_sigma` (rad, normal) makes `line`: a lateral miss at
/// the ghost ball turns the object ball by e / (2R cos cut), and the pocket takes it within about
/// 3 cm of its line (less when it comes in at an angle to the pocket's opening). 1 when
/// `yaw_sigma` is 0.
double makeChance(const PotLine& line, double yaw_sigma, const TableView& view);

/// How far ahead a leave is looked at.
enum class LookAhead {
  NextShot,  ///< the chances of the next pot alone
  TwoShots,  ///< each next pot also weighed by the position it offers on the shot after it
};

/// What the leave `balls` offers the shooter of `state`, in [0, 1]: 1 with the cue ball in hand,
/// 0 once the game is over. Over the three best balls b (each by its best clear line), the chance
/// that at least one would be made were each tried in turn, each counted as
/// makeChance(b) x follow(b): follow is 1 when looking at the next shot only or when b ends the
/// game, else (TwoShots) how well the cue ball can be placed for the ball after b, from the best
/// spots of a fan of cue-ball paths off b (follow, stun and draw, each at several lengths, the
/// cushions reflecting them) where the next pot from there has the best chances.
double leaveValue(const std::vector<physics::Ball>& balls, const rules::GameState& state,
                  const TableView& view, double yaw_sigma, LookAhead look);

}  // namespace pool::bot
