// One switch per enum between the server's domain types and pool.idl.
#include "wire_enums.h"

#include "net/wire_fields.h"

namespace pool::server {

pool_MatchPhase toWire(MatchPhase phase) {
  switch (phase) {
    case MatchPhase::Lobby:
      return pool_PHASE_LOBBY;
    case MatchPhase::Break:
      return pool_PHASE_BREAK;
    case MatchPhase::Open:
      return pool_PHASE_OPEN;
    case MatchPhase::Assigned:
      return pool_PHASE_ASSIGNED;
    case MatchPhase::Over:
      return pool_PHASE_OVER;
    case MatchPhase::Closed:
      return pool_PHASE_CLOSED;
  }
  return pool_PHASE_LOBBY;
}

pool_BallGroup toWire(rules::Group group) {
  switch (group) {
    case rules::Group::None:
      return pool_GROUP_NONE;
    case rules::Group::Solids:
      return pool_GROUP_SOLIDS;
    case rules::Group::Stripes:
      return pool_GROUP_STRIPES;
  }
  return pool_GROUP_NONE;
}

pool_BallInHandKind toWire(rules::BallInHand in_hand) {
  switch (in_hand) {
    case rules::BallInHand::None:
      return pool_IN_HAND_NONE;
    case rules::BallInHand::Anywhere:
      return pool_IN_HAND_ANYWHERE;
    case rules::BallInHand::BehindHeadString:
      return pool_IN_HAND_BEHIND_HEAD_STRING;
  }
  return pool_IN_HAND_NONE;
}

pool_ShotOption toWire(rules::Choice choice) {
  switch (choice) {
    case rules::Choice::PlayOn:
      return pool_OPTION_PLAY_ON;
    case rules::Choice::BallInHand:
      return pool_OPTION_BALL_IN_HAND;
    case rules::Choice::RespotEight:
      return pool_OPTION_RESPOT_EIGHT;
    case rules::Choice::ReBreak:
      return pool_OPTION_REBREAK;
    case rules::Choice::OpponentReBreaks:
      return pool_OPTION_OPPONENT_REBREAKS;
  }
  return pool_OPTION_NONE;
}

pool_FoulCode toWire(rules::Foul foul) {
  switch (foul) {
    case rules::Foul::CueBallPocketed:
      return pool_FOUL_CUE_BALL_POCKETED;
    case rules::Foul::CueBallOffTable:
      return pool_FOUL_CUE_BALL_OFF_TABLE;
    case rules::Foul::NoBallHit:
      return pool_FOUL_NO_BALL_HIT;
    case rules::Foul::WrongBallFirst:
      return pool_FOUL_WRONG_BALL_FIRST;
    case rules::Foul::NoCushionAfterContact:
      return pool_FOUL_NO_CUSHION_AFTER_CONTACT;
    case rules::Foul::ObjectBallOffTable:
      return pool_FOUL_OBJECT_BALL_OFF_TABLE;
    case rules::Foul::ShotClockExpired:
      return pool_FOUL_SHOT_CLOCK_EXPIRED;
    case rules::Foul::IllegalBreak:
      return pool_FOUL_ILLEGAL_BREAK;
    case rules::Foul::BehindHeadStringDirect:
      return pool_FOUL_BEHIND_HEAD_STRING_DIRECT;
  }
  return pool_FOUL_NO_BALL_HIT;
}

pool_GameEnd toWire(rules::GameEnd end) {
  switch (end) {
    case rules::GameEnd::None:
      return pool_END_NONE;
    case rules::GameEnd::EightPocketed:
      return pool_END_EIGHT_POCKETED;
    case rules::GameEnd::EightOnFoul:
      return pool_END_EIGHT_ON_FOUL;
    case rules::GameEnd::EightBeforeGroupCleared:
      return pool_END_EIGHT_BEFORE_GROUP_CLEARED;
    case rules::GameEnd::EightWithLastGroupBall:
      return pool_END_EIGHT_WITH_LAST_GROUP_BALL;
    case rules::GameEnd::EightWrongPocket:
      return pool_END_EIGHT_WRONG_POCKET;
    case rules::GameEnd::EightOffTable:
      return pool_END_EIGHT_OFF_TABLE;
    case rules::GameEnd::Forfeit:
      return pool_END_FORFEIT;
  }
  return pool_END_NONE;
}

pool_RejectReason toWire(Reject reason) {
  switch (reason) {
    case Reject::None:
      return pool_REJECT_NONE;
    case Reject::Malformed:
      return pool_REJECT_MALFORMED;
    case Reject::NoSuchMatch:
      return pool_REJECT_NO_SUCH_MATCH;
    case Reject::WrongSeat:
      return pool_REJECT_WRONG_SEAT;
    case Reject::BadToken:
      return pool_REJECT_BAD_TOKEN;
    case Reject::MatchOver:
      return pool_REJECT_MATCH_OVER;
    case Reject::NotYourTurn:
      return pool_REJECT_NOT_YOUR_TURN;
    case Reject::BallsMoving:
      return pool_REJECT_BALLS_MOVING;
    case Reject::StaleSequence:
      return pool_REJECT_STALE_SEQUENCE;
    case Reject::OptionRequired:
      return pool_REJECT_OPTION_REQUIRED;
    case Reject::OptionNotOffered:
      return pool_REJECT_OPTION_NOT_OFFERED;
    case Reject::IllegalPlacement:
      return pool_REJECT_ILLEGAL_PLACEMENT;
    case Reject::BadCall:
      return pool_REJECT_BAD_CALL;
    case Reject::BadSignature:
      return pool_REJECT_BAD_SIGNATURE;
    case Reject::Unsigned:
      return pool_REJECT_UNSIGNED;
  }
  return pool_REJECT_MALFORMED;
}

pool_JoinAction toWire(JoinAction action) {
  switch (action) {
    case JoinAction::Seat:
      return pool_JOIN_SEAT;
    case JoinAction::Spectate:
      return pool_JOIN_SPECTATE;
    case JoinAction::Rejoin:
      return pool_JOIN_REJOIN;
    case JoinAction::Leave:
      return pool_JOIN_LEAVE;
    case JoinAction::Rematch:
      return pool_JOIN_REMATCH;
  }
  return pool_JOIN_SEAT;
}

pool_JoinOutcome toWire(JoinOutcome outcome) {
  switch (outcome) {
    case JoinOutcome::Accepted:
      return pool_JOIN_ACCEPTED;
    case JoinOutcome::NoSuchMatch:
      return pool_JOIN_NO_SUCH_MATCH;
    case JoinOutcome::SeatTaken:
      return pool_JOIN_SEAT_TAKEN;
    case JoinOutcome::MatchFull:
      return pool_JOIN_MATCH_FULL;
    case JoinOutcome::BadToken:
      return pool_JOIN_BAD_TOKEN;
    case JoinOutcome::BadName:
      return pool_JOIN_BAD_NAME;
    case JoinOutcome::VersionMismatch:
      return pool_JOIN_VERSION_MISMATCH;
    case JoinOutcome::NotAllowed:
      return pool_JOIN_NOT_ALLOWED;
    case JoinOutcome::ServerFull:
      return pool_JOIN_SERVER_FULL;
    case JoinOutcome::Unsigned:
      return pool_JOIN_UNSIGNED;
    case JoinOutcome::BadSignature:
      return pool_JOIN_BAD_SIGNATURE;
    case JoinOutcome::StaleSequence:
      return pool_JOIN_STALE_SEQUENCE;
  }
  return pool_JOIN_NOT_ALLOWED;
}

std::optional<JoinAction> joinActionFromWire(const pool_JoinAction& action) {
  // The value arrives as a raw integer: anything outside the enumerators is refused.
  switch (net::rawValue(action)) {
    case pool_JOIN_SEAT:
      return JoinAction::Seat;
    case pool_JOIN_SPECTATE:
      return JoinAction::Spectate;
    case pool_JOIN_REJOIN:
      return JoinAction::Rejoin;
    case pool_JOIN_LEAVE:
      return JoinAction::Leave;
    case pool_JOIN_REMATCH:
      return JoinAction::Rematch;
  }
  return std::nullopt;
}

}  // namespace pool::server
