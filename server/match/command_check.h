// The checks of one shot command against its match, in a fixed order, before anything runs.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "physics/ball.h"
#include "protocol/shot_request.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/verdict.h"
#include "server/match/reject.h"
#include "server/match/seat.h"

namespace pool::server {

class Match;

/// A command that passed every check, ready to run.
struct ShotPlan {
  rules::GameState state;                ///< the state the shot is judged in (any choice applied)
  std::vector<physics::Ball> before;     ///< the table at the strike (respots, placement applied)
  rules::Intent intent;                  ///< the call or safety
  std::optional<rules::Verdict> choice;  ///< the answer to a pending choice, applied
  bool shoots = true;                    ///< false: a choice that re-racks, without a shot
};

/// A plan, or why there is none.
struct CheckedCommand {
  Rejection rejection;
  ShotPlan plan;  ///< meaningful only when accepted
  /// The seat's key signed it: its sequence number is used up, whatever the later checks say.
  bool signature_valid = false;
};

/// What names a seat's holding in a signed command.
struct HolderFields {
  int seat = 0;
  std::uint64_t token = 0;
  std::uint32_t seq = 0;
  bool has_signature = false;
};

/// Checks 2–5 below for any signed command of a seat (shot or practice): wrong seat, bad token,
/// unsigned, stale sequence, then `signed_by(seat)`, the command's signature checked against the
/// seat's key.
RejectCheck checkHolder(const Match& match, const HolderFields& fields,
                        const std::function<bool(const Seat&)>& signed_by);

/// Checks `command` against `match` and stops at the first failure, in this order:
/// 1. malformed: shot values the table's physics refuses (net's validateShotCommand has already
///    checked the wire fields, and the registry the match id);
/// 2. wrong seat (not 0/1, or free), then bad token;
/// 3. unsigned: no signature;
/// 4. stale sequence: seq must exceed the seat's last used one (a replay of any command the
///    seat's key signed ends here);
/// 5. bad signature: not the seat key's Ed25519 signature of the command's fields (the one
///    costly check, made only once the cheap ones passed). From here on the command is the
///    seat holder's own and its number is used up whatever follows (signature_valid), so a
///    refused command cannot be replayed later in a state where it would pass;
/// 6. match over (or closed);
/// 7. not your turn (or the match has not started; at a practice table either seat may shoot);
/// 8. balls moving (a shot's frames are still being published);
/// 9. option required / not offered (a pending choice is applied here, to copies);
/// 10. illegal placement: a placement without ball in hand, a refused spot, or no placement
///    while the cue ball in hand is off the table;
/// 11. bad call: the rules' intent check (a legal group's ball and a pocket name, or a safety;
///    none at a practice table).
/// Nothing is changed; the plan says what to run.
CheckedCommand checkCommand(const Match& match, const protocol::ShotRequest& command);

}  // namespace pool::server
