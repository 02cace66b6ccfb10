// Names of the reasons a shot command is refused.
#include "match/reject.h"

namespace pool::server {

const char* toString(Reject reason) {
  switch (reason) {
    case Reject::None: return "none";
    case Reject::Malformed: return "malformed";
    case Reject::NoSuchMatch: return "no_such_match";
    case Reject::WrongSeat: return "wrong_seat";
    case Reject::BadToken: return "bad_token";
    case Reject::MatchOver: return "match_over";
    case Reject::NotYourTurn: return "not_your_turn";
    case Reject::BallsMoving: return "balls_moving";
    case Reject::StaleSequence: return "stale_sequence";
    case Reject::OptionRequired: return "option_required";
    case Reject::OptionNotOffered: return "option_not_offered";
    case Reject::IllegalPlacement: return "illegal_placement";
    case Reject::BadCall: return "bad_call";
    case Reject::BadSignature: return "bad_signature";
  }
  return "unknown";
}

}  // namespace pool::server
