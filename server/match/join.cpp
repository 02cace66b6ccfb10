// Names of join actions and outcomes.
#include "match/join.h"

namespace pool::server {

const char* toString(JoinAction action) {
  switch (action) {
    case JoinAction::Seat: return "seat";
    case JoinAction::Spectate: return "spectate";
    case JoinAction::Rejoin: return "rejoin";
    case JoinAction::Leave: return "leave";
    case JoinAction::Rematch: return "rematch";
  }
  return "unknown";
}

const char* toString(JoinOutcome outcome) {
  switch (outcome) {
    case JoinOutcome::Accepted: return "accepted";
    case JoinOutcome::NoSuchMatch: return "no_such_match";
    case JoinOutcome::SeatTaken: return "seat_taken";
    case JoinOutcome::MatchFull: return "match_full";
    case JoinOutcome::BadToken: return "bad_token";
    case JoinOutcome::BadName: return "bad_name";
    case JoinOutcome::VersionMismatch: return "version_mismatch";
    case JoinOutcome::NotAllowed: return "not_allowed";
    case JoinOutcome::ServerFull: return "server_full";
  }
  return "unknown";
}

}  // namespace pool::server
