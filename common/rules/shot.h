// One shot as the referee receives it: the table before, the shooter's intent, the event log, the
// table after.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "physics/ball.h"
#include "physics/events.h"
#include "rules/game_state.h"

namespace pool::rules {

/// What the shooter declared before the shot.
struct Intent {
  std::optional<int> ball;  ///< called ball (1–15; snooker: the nominated ball, 1–21)
  std::string pocket;       ///< called pocket (see pocketNames()); with `ball`
  bool safety = false;      ///< a declared safety: the turn passes whatever falls
  std::optional<Choice>
      choice;  ///< the answer to pending options (PlayOn or BallInHand with a shot)

  /// A called ball and pocket.
  static Intent call(int ball, std::string pocket);
  /// A declared safety.
  static Intent safe();
  /// Nothing declared (the break; uncalled shots in casual play).
  static Intent none() { return {}; }
};

/// One shot: balls before and after (pocketed ones may be listed too), the intent and the log.
struct Shot {
  std::vector<physics::Ball>
      before;  ///< the table when the cue was struck (cue ball already placed)
  Intent intent;
  physics::EventLog
      events;  ///< in time order, starting with the strike; may be empty on a time-out
  std::vector<physics::Ball> after;  ///< every ball at the end
  bool clock_expired = false;        ///< the shot clock ran out (set by whoever keeps the clock)
};

}  // namespace pool::rules
