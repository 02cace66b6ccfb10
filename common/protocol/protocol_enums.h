// The protocol's enums in domain terms (no DDS types), shared by the server and the clients.
#pragma once

#include <cstdint>

namespace pool::protocol {

/// Where a match stands (MatchPhase of pool.idl).
enum class MatchPhase : std::uint8_t { Lobby, Break, Open, Assigned, Over, Closed };

/// What a JoinRequest asks for (JoinAction of pool.idl).
enum class JoinAction : std::uint8_t { Seat, Spectate, Rejoin, Leave, Rematch, Concede, Enter };

/// The outcome of a JoinRequest (JoinOutcome of pool.idl).
enum class JoinOutcome : std::uint8_t {
  Accepted,
  NoSuchMatch,
  SeatTaken,
  MatchFull,
  BadToken,
  BadName,
  VersionMismatch,
  NotAllowed,
  ServerFull,
  Unsigned,       ///< a request that changes a seat carried no signature
  BadSignature,   ///< not the signature of the key that binds (or is bound to) the seat
  StaleSequence,  ///< seq not above the last one that key used
};

/// Why the server refused a shot command (RejectReason of pool.idl, in its order: the wire
/// conversion relies on it, net/message_convert.cpp checks every value).
enum class RejectReason : std::uint8_t {
  None,              ///< accepted
  Malformed,         ///< a field is non-finite, out of range or not a valid value
  NoSuchMatch,       ///< no match of that id on this server
  WrongSeat,         ///< nobody sits in that seat
  BadToken,          ///< the seat token does not match the seat's
  NotYourTurn,       ///< the other seat is to shoot (or the match has not started)
  BallsMoving,       ///< a shot is still being published
  StaleSequence,     ///< seq not above the seat's last accepted one
  IllegalPlacement,  ///< the cue ball cannot be placed there (or must be placed)
  OptionRequired,    ///< the rules offered a choice and none was made
  OptionNotOffered,  ///< a choice the rules did not offer
  BadCall,           ///< the called ball or pocket is not allowed (or no call in standard play)
  MatchOver,         ///< the match has a winner (or was closed)
  BadSignature,      ///< not the seat key's signature of the command's fields
  Unsigned,          ///< no signature at all
  NotPractice,       ///< a practice command at a table that is not a practice table
  BadPractice,       ///< a practice command the table cannot carry out (nothing to undo, ...)
};

/// True for the refusals the server makes after a command's signature checked out (its sequence
/// number is then used up, server/README.md); false for those before it, and for None.
bool refusedAfterSignature(RejectReason reason);

/// snake_case names, e.g. "stale_sequence"; "unknown" for a value outside the enum.
const char* toString(MatchPhase phase);
const char* toString(JoinAction action);
const char* toString(JoinOutcome outcome);
const char* toString(RejectReason reason);

}  // namespace pool::protocol
