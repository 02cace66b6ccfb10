// The WPA rotation games, 9-ball and 10-ball: checks a shooter's intent, judges a shot, applies the
// choices it offers.
#pragma once

#include <cstdint>
#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/table_context.h"
#include "rules/verdict.h"

namespace pool::rules {

/// Which rotation game: 9-ball (balls 1–9, the 9 wins) or 10-ball (balls 1–10, called shots, the
/// 10 wins when called).
enum class Rotation : std::uint8_t { NineBall, TenBall };

const char* toString(Rotation game);  ///< "9-ball", "10-ball"

/// Options of a rotation match.
struct RotationConfig {
  Rotation game = Rotation::NineBall;
  /// A stalemate (re-rack, same breaker) after this many consecutive shots that pocket no object
  /// ball; 0: never.
  int stalemate_turns = 40;
};

/// The ball that wins the rack: 9 or 10.
int rackBall(Rotation game);

/// The lowest-numbered object ball on the table in `balls`; -1 when there is none.
int lowestBall(const std::vector<physics::Ball>& balls);

/// Object balls the shooter may hit first: the lowest one on the table (on the break and on a
/// push-out, too: the push-out only excuses missing it).
std::vector<int> rotationFirstBalls(const std::vector<physics::Ball>& balls);

/// Checks a declared intent before the shot. Refused: the game is over; options are pending and
/// none (or one not offered) is chosen, or the choice needs no shot (apply it first); a choice
/// when none is pending; a call and a safety at once; a called ball not on the table or not in
/// the game, or an unknown pocket; in 10-ball after the break (a push-out aside), no call and no
/// safety. 9-ball needs no call: a call given is checked, and then ignored.
Check<> checkRotationIntent(const GameState& state, const Intent& intent,
                            const std::vector<physics::Ball>& balls, const RotationConfig& config);

/// Judges one shot. Refused (never judged) when the intent fails checkRotationIntent, the cue
/// ball in hand was placed illegally, or the shot fails checkShot. A shot clock that ran out with
/// no strike (empty log) is judged as a foul without a shot.
///
/// The rules (WPA): the cue ball must first hit the lowest ball on the table, and after that
/// contact a ball must reach a cushion or fall. A foul gives the opponent the cue ball in hand
/// anywhere; balls pocketed on it stay down, but the rack ball (9 or 10) is re-spotted, as is
/// a rack ball driven off the table (other balls off the table stay off). The third foul in a row
/// of one player loses the rack. The break must pocket a ball or drive four object balls to a
/// cushion: otherwise a foul (9-ball: ball in hand to the opponent, who may also push out;
/// 10-ball: the opponent plays on with ball in hand, or has the balls re-racked and breaks, or
/// has the breaker break again). The 9 on a legal break wins; the 10 on the break is re-spotted.
/// The shot after the break may be a push-out (Choice::PushOut): no contact fouls, balls
/// pocketed stay down (the rack ball re-spotted), and the opponent chooses to play on or pass it
/// back. 9-ball: any ball pocketed on a legal shot keeps the turn, the 9 wins. 10-ball: only the
/// called ball in the called pocket keeps the turn, the 10 called wins; any other ball pocketed
/// stays down (the 10 re-spotted) and the opponent chooses to play on or pass it back. A declared
/// safety passes the turn whatever falls (the rack ball re-spotted).
Result<Verdict> judgeRotation(const GameState& state, const Shot& shot, const TableContext& table,
                              const RotationConfig& config);

/// Applies the choice of a pending option without a shot (PassBack, ReBreak, OpponentReBreaks),
/// or the one a shot starts with (PlayOn, PushOut): the verdict's next state is the state to
/// shoot from.
Result<Verdict> applyRotationChoice(const GameState& state, Choice choice);

}  // namespace pool::rules
