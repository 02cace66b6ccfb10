// Three-cushion's rules (UMB, World Rules of Carom Billiard): a point, innings, runs, the game.
#pragma once

#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/table_context.h"
#include "rules/verdict.h"

namespace pool::rules {

/// Ball ids of a three-cushion game: the breaker plays the white, the other player the yellow;
/// the red is nobody's.
inline constexpr int kCaromWhite = 0;
inline constexpr int kCaromYellow = 1;
inline constexpr int kCaromRed = 2;

/// How a game of three-cushion is played.
struct ThreeCushionConfig {
  int points_to = 5;  ///< the points that win the game
};

/// The ball `seat` strikes: the white for the breaker, the yellow for the other player.
int caromBallOf(const GameState& state, int seat);

/// What the cue ball of a three-cushion shot did (from a checked event log).
struct CaromFacts {
  int first = -1;   ///< the object ball it touched first; -1: none
  int second = -1;  ///< the other object ball, when it touched that one too; -1: not
  /// Cushions it touched before it first touched the second object ball (every touch counts,
  /// the same cushion again included); all its cushions when it never did.
  int cushions = 0;
  std::vector<int> off_table;  ///< balls that left the table, in time order

  /// UMB: a point is made when the cue ball touches both object balls and, before it touches
  /// the second, at least three cushions.
  bool point() const { return second >= 0 && cushions >= 3; }
};

/// The facts of `shot` struck with `cue` (checked first: the log must start with its strike).
Result<CaromFacts> caromFacts(const Shot& shot, int cue);

/// Refuses an intent three-cushion has no use for: a called ball or pocket, a safety, a choice.
Check<> checkCaromIntent(const Intent& intent);

/// Judges one shot of three-cushion (the game's opening is the state's Break phase):
/// - a point scores 1 and the shooter plays on; the points that win end the game (PointsReached);
/// - no point ends the inning: the turn passes, the run ends (the high run kept);
/// - fouls end the inning and score nothing: a ball off the table (CueBallOffTable for the
///   shooter's ball, ObjectBallOffTable for another; the ball is re-spotted), the opening shot not
///   hitting the red first (WrongBallFirst), the shot clock run out (ShotClockExpired);
/// - a ball that left the table goes back on its spot (the red on the top spot, the shooter's
///   ball on the bottom spot, the other on the centre spot), or on the spot of the ball that
///   holds its own, or the free one.
/// The cue ball is never in hand; there are no choices.
Result<Verdict> judgeThreeCushion(const GameState& state, const Shot& shot,
                                  const TableContext& table, const ThreeCushionConfig& config);

}  // namespace pool::rules
