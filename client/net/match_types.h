// The protocol's published messages as the client names them (they live in common/protocol).
#pragma once

#include "protocol/match_messages.h"
#include "protocol/protocol_enums.h"

namespace pool::client {

using protocol::gameStateOf;
using protocol::inPlay;
using protocol::JoinAction;
using protocol::JoinAnswer;
using protocol::JoinOutcome;
using protocol::LobbyEntry;
using protocol::MatchGone;
using protocol::MatchPhase;
using protocol::MatchView;
using protocol::RejectReason;
using protocol::SeatView;
using protocol::ShotReport;
using protocol::TableFrame;
using protocol::toString;

}  // namespace pool::client
