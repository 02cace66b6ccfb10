// Checks a received ShotCommand's fields on their own: representable, finite, in range. Whose turn
// it is, the seat token, the sequence number and the legality of a placement are the server's.
#pragma once

#include <cstdint>
#include <numbers>
#include <string>
#include <string_view>

#include "core/check.h"
#include "net/incoming_command.h"
#include "net/messages.h"
#include "net/wire_fields.h"
#include "protocol/command_limits.h"

namespace pool::net {

/// What is wrong with a ShotCommand's fields, in the order they are checked.
enum class CommandProblem : std::uint8_t {
  None,
  BadMatchId,           ///< empty, unterminated or not printable
  BadSeat,              ///< not 0 or 1
  NonFinite,            ///< a number is NaN or infinite
  BadOption,            ///< not a protocol::ShotOption value
  SpeedOutOfRange,      ///< not in (0, max_speed]
  ElevationOutOfRange,  ///< not in [0, max_elevation]
  TipOutOfRange,        ///< sqrt(side² + height²) beyond the miscue limit
  YawOutOfRange,        ///< |yaw| beyond max_abs_yaw
  BadCall,  ///< a called ball outside 1–21, a bad pocket name, or a pocket without a ball
  PlacementOutOfRange,  ///< cue-ball placement off the table's playing surface
  BadSignature,         ///< longer than 64 bytes, or a length without a buffer
};

const char* toString(CommandProblem problem);  ///< snake_case, e.g. "speed_out_of_range"

/// The verdict on a command's fields: its problem and "<field>: <reason>".
using CommandCheck = Check<CommandProblem>;

/// True when `text` is a non-empty id of printable ASCII without spaces.
bool printableId(std::string_view text);

/// The match id and seat that every signed player command (a shot, a practice command) names,
/// checked alike: a non-empty printable id, and seat 0 or 1.
template <class Command>
CommandCheck checkMatchAndSeat(const Command& command) {
  if (!terminated(command.match) || !printableId(textOf(command.match))) {
    return CommandCheck::refuse(CommandProblem::BadMatchId,
                                "match: must be a non-empty printable id");
  }
  if (command.seat != 0 && command.seat != 1) {
    return CommandCheck::refuse(CommandProblem::BadSeat, "seat: must be 0 or 1");
  }
  return CommandCheck::pass();
}

/// Checks every field of `command` against `limits`. Shot values (speed, elevation, tip, yaw) are
/// range-checked only when the option answers with a shot; every number must be finite always.
CommandCheck validateShotCommand(const pool_ShotCommand& command,
                                 const protocol::CommandLimits& limits = {});

/// Reads `command` off the wire: its fields checked against `limits`, then converted.
IncomingCommand readCommand(const pool_ShotCommand& command,
                            const protocol::CommandLimits& limits = {});

}  // namespace pool::net
