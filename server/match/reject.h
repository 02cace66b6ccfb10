// Why the server refused a shot command: the reasons of pool.idl's RejectReason, in domain terms.
#pragma once

#include <cstdint>
#include <string>

namespace pool::server {

/// Why a command was refused, in the order the server checks (RejectReason of pool.idl).
enum class Reject : std::uint8_t {
  None,              ///< accepted
  Malformed,         ///< a field is non-finite, out of range or not a valid value
  NoSuchMatch,       ///< no match of that id on this server
  WrongSeat,         ///< nobody sits in that seat
  BadToken,          ///< the seat token does not match the seat's
  MatchOver,         ///< the match has a winner (or was closed)
  NotYourTurn,       ///< the other seat is to shoot (or the match has not started)
  BallsMoving,       ///< a shot is still being published
  StaleSequence,     ///< seq not above the seat's last accepted one
  OptionRequired,    ///< the rules offered a choice and none was made
  OptionNotOffered,  ///< a choice the rules did not offer
  IllegalPlacement,  ///< the cue ball cannot be placed there (or must be placed)
  BadCall,           ///< the called ball or pocket is not allowed (or no call in standard play)
  BadSignature,      ///< reserved for signed commands
};

const char* toString(Reject reason);  ///< snake_case, e.g. "stale_sequence"

/// A refusal: the reason and one human-readable line.
struct Rejection {
  Reject reason = Reject::None;
  std::string text;  ///< empty when accepted

  bool accepted() const { return reason == Reject::None; }
  static Rejection none() { return {}; }
};

}  // namespace pool::server
