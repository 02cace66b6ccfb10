// The checks of one shot command against its match, in a fixed order, before anything runs.
#pragma once

#include <optional>
#include <vector>

#include "match/reject.h"
#include "net/shot_request.h"
#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/verdict.h"

namespace pool::server {

class Match;

/// A command that passed every check, ready to run.
struct ShotPlan {
  rules::GameState state;             ///< the state the shot is judged in (any choice applied)
  std::vector<physics::Ball> before;  ///< the table at the strike (respots, placement applied)
  rules::Intent intent;               ///< the call or safety
  std::optional<rules::Verdict> choice;  ///< the answer to a pending choice, applied
  bool shoots = true;                    ///< false: a choice that re-racks, without a shot
};

/// A plan, or why there is none.
struct CheckedCommand {
  Rejection rejection;
  ShotPlan plan;  ///< meaningful only when accepted
};

/// The rules' choice an option answers; empty for ShotOption::None.
std::optional<rules::Choice> choiceOf(net::ShotOption option);

/// Checks `command` against `match` and stops at the first failure, in this order:
/// 1. malformed: shot values the table's physics refuses (net's validateShotCommand has already
///    checked the wire fields, and the registry the match id);
/// 2. wrong seat (not 0/1, or free), then bad token;
/// 3. match over (or closed);
/// 4. not your turn (or the match has not started);
/// 5. balls moving (a shot's frames are still being published);
/// 6. stale sequence: seq must exceed the seat's last accepted one (a refused command does not
///    use up its number, so it may be sent again corrected with the same seq);
/// 7. option required / not offered (a pending choice is applied here, to copies);
/// 8. illegal placement: a placement without ball in hand, a refused spot, or no placement
///    while the cue ball in hand is off the table;
/// 9. bad call: the rules' intent check (a legal group's ball and a pocket name, or a safety).
/// Nothing is changed; the plan says what to run.
CheckedCommand checkCommand(const Match& match, const net::ShotRequest& command);

}  // namespace pool::server
