// The server's domain enums as pool.idl's wire enums, and back for what clients send.
#pragma once

#include <optional>

#include "match/join.h"
#include "match/match_types.h"
#include "match/reject.h"
#include "net/messages.h"
#include "rules/game_state.h"
#include "rules/verdict.h"

namespace pool::server {

pool_MatchPhase toWire(MatchPhase phase);
pool_BallGroup toWire(rules::Group group);
pool_BallInHandKind toWire(rules::BallInHand in_hand);
pool_ShotOption toWire(rules::Choice choice);
pool_FoulCode toWire(rules::Foul foul);
pool_GameEnd toWire(rules::GameEnd end);
pool_RejectReason toWire(Reject reason);
pool_JoinAction toWire(JoinAction action);
pool_JoinOutcome toWire(JoinOutcome outcome);

/// A join action from the wire; empty for a value that is no enumerator.
std::optional<JoinAction> joinActionFromWire(const pool_JoinAction& action);

}  // namespace pool::server
