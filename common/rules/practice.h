// The practice rule set: one player, no fouls, re-rack and re-place balls on demand.
#pragma once

#include <cstdint>
#include <vector>

#include "core/result.h"
#include "physics/ball.h"
#include "rules/game_rules.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/table_context.h"
#include "rules/verdict.h"
#include "table/rack.h"

namespace pool::rules {

/// The highest ball id at a practice table of `game`: a pool game's 15, snooker's black
/// (table::kSnookerBlack, 21), three-cushion's red (kCaromRed, 2).
int practiceMaxBallId(Game game);

/// The practice state: seat 0 shoots every shot, the cue ball in hand anywhere to start.
GameState practiceState();

/// Judges a practice shot: never a foul, seat 0 shoots again; balls pocketed or off the table stay
/// there; a lost cue ball comes back in hand anywhere; balls the watchdog removed are re-spotted.
/// A shot that fails checkShot is refused; the intent is ignored.
Result<Verdict> judgePractice(const Shot& shot, const TableContext& table);

/// A full 8-ball rack (table::rackBalls with `seed`) and the cue ball on the head spot, at rest.
std::vector<physics::Ball> practiceRack(const TableContext& table, std::uint64_t seed);

/// Puts balls where the player asks at a practice table of `game`, one after another (each in
/// the table plane, at rest on the slate; a ball not yet listed is added). Refused, with nothing
/// changed, if a position is off the slate, over a pocket, overlaps a ball, or an id is not one
/// of the game's, 0 to practiceMaxBallId ("ball 22: not a ball id (0-21)").
Result<std::vector<physics::Ball>> placeBalls(const std::vector<physics::Ball>& balls,
                                              const std::vector<table::BallPlacement>& moves,
                                              const TableContext& table, Game game);

}  // namespace pool::rules
