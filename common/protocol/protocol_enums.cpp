// Names of the protocol's enums.
#include "protocol/protocol_enums.h"

namespace pool::protocol {

const char* toString(MatchPhase phase) {
  switch (phase) {
    case MatchPhase::Lobby:
      return "lobby";
    case MatchPhase::Break:
      return "break";
    case MatchPhase::Open:
      return "open";
    case MatchPhase::Assigned:
      return "assigned";
    case MatchPhase::Over:
      return "over";
    case MatchPhase::Closed:
      return "closed";
  }
  return "unknown";
}

const char* toString(JoinAction action) {
  switch (action) {
    case JoinAction::Seat:
      return "seat";
    case JoinAction::Spectate:
      return "spectate";
    case JoinAction::Rejoin:
      return "rejoin";
    case JoinAction::Leave:
      return "leave";
    case JoinAction::Rematch:
      return "rematch";
    case JoinAction::Concede:
      return "concede";
    case JoinAction::Enter:
      return "enter";
  }
  return "unknown";
}

const char* toString(JoinOutcome outcome) {
  switch (outcome) {
    case JoinOutcome::Accepted:
      return "accepted";
    case JoinOutcome::NoSuchMatch:
      return "no_such_match";
    case JoinOutcome::SeatTaken:
      return "seat_taken";
    case JoinOutcome::MatchFull:
      return "match_full";
    case JoinOutcome::BadToken:
      return "bad_token";
    case JoinOutcome::BadName:
      return "bad_name";
    case JoinOutcome::VersionMismatch:
      return "version_mismatch";
    case JoinOutcome::NotAllowed:
      return "not_allowed";
    case JoinOutcome::ServerFull:
      return "server_full";
    case JoinOutcome::Unsigned:
      return "unsigned";
    case JoinOutcome::BadSignature:
      return "bad_signature";
    case JoinOutcome::StaleSequence:
      return "stale_sequence";
  }
  return "unknown";
}

const char* toString(RejectReason reason) {
  switch (reason) {
    case RejectReason::None:
      return "none";
    case RejectReason::Malformed:
      return "malformed";
    case RejectReason::NoSuchMatch:
      return "no_such_match";
    case RejectReason::WrongSeat:
      return "wrong_seat";
    case RejectReason::BadToken:
      return "bad_token";
    case RejectReason::NotYourTurn:
      return "not_your_turn";
    case RejectReason::BallsMoving:
      return "balls_moving";
    case RejectReason::StaleSequence:
      return "stale_sequence";
    case RejectReason::IllegalPlacement:
      return "illegal_placement";
    case RejectReason::OptionRequired:
      return "option_required";
    case RejectReason::OptionNotOffered:
      return "option_not_offered";
    case RejectReason::BadCall:
      return "bad_call";
    case RejectReason::MatchOver:
      return "match_over";
    case RejectReason::BadSignature:
      return "bad_signature";
    case RejectReason::Unsigned:
      return "unsigned";
    case RejectReason::NotPractice:
      return "not_practice";
    case RejectReason::BadPractice:
      return "bad_practice";
  }
  return "unknown";
}

bool refusedAfterSignature(RejectReason reason) {
  switch (reason) {
    case RejectReason::MatchOver:
    case RejectReason::NotYourTurn:
    case RejectReason::BallsMoving:
    case RejectReason::OptionRequired:
    case RejectReason::OptionNotOffered:
    case RejectReason::IllegalPlacement:
    case RejectReason::BadCall:
    case RejectReason::NotPractice:
    case RejectReason::BadPractice:
      return true;
    default:
      return false;
  }
}

}  // namespace pool::protocol
