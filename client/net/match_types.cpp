// Names of the client's protocol enums and the rules' view of a match state.
#include "client/net/match_types.h"

namespace pool::client {

const char* toString(MatchPhase phase) {
  switch (phase) {
    case MatchPhase::Lobby: return "lobby";
    case MatchPhase::Break: return "break";
    case MatchPhase::Open: return "open";
    case MatchPhase::Assigned: return "assigned";
    case MatchPhase::Over: return "over";
    case MatchPhase::Closed: return "closed";
  }
  return "unknown";
}

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

const char* toString(RejectReason reason) {
  switch (reason) {
    case RejectReason::None: return "none";
    case RejectReason::Malformed: return "malformed";
    case RejectReason::NoSuchMatch: return "no_such_match";
    case RejectReason::WrongSeat: return "wrong_seat";
    case RejectReason::BadToken: return "bad_token";
    case RejectReason::NotYourTurn: return "not_your_turn";
    case RejectReason::BallsMoving: return "balls_moving";
    case RejectReason::StaleSequence: return "stale_sequence";
    case RejectReason::IllegalPlacement: return "illegal_placement";
    case RejectReason::OptionRequired: return "option_required";
    case RejectReason::OptionNotOffered: return "option_not_offered";
    case RejectReason::BadCall: return "bad_call";
    case RejectReason::MatchOver: return "match_over";
    case RejectReason::BadSignature: return "bad_signature";
  }
  return "unknown";
}

bool inPlay(MatchPhase phase) {
  return phase == MatchPhase::Break || phase == MatchPhase::Open || phase == MatchPhase::Assigned;
}

rules::GameState gameStateOf(const MatchView& view) {
  rules::GameState state;
  switch (view.phase) {
    case MatchPhase::Break: state.phase = rules::Phase::Break; break;
    case MatchPhase::Open: state.phase = rules::Phase::Open; break;
    case MatchPhase::Assigned: state.phase = rules::Phase::Assigned; break;
    default: state.phase = rules::Phase::Over; break;
  }
  state.shooter = view.shooter == 1 ? 1 : 0;
  state.breaker = view.breaker == 1 ? 1 : 0;
  state.groups = {view.seats[0].group, view.seats[1].group};
  state.ball_in_hand = view.ball_in_hand;
  state.options = view.options;
  state.winner = view.winner;
  state.end = view.end;
  return state;
}

}  // namespace pool::client
