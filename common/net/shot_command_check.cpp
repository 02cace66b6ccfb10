// Field checks of a received ShotCommand: representable, finite, in range.
#include "net/shot_command_check.h"

#include "net/convert.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string_view>

#include "net/wire_fields.h"

namespace pool::net {

namespace {

using Check = std::optional<CommandCheck>;

CommandCheck fail(CommandProblem problem, std::string text) {
  return CommandCheck::refuse(problem, std::move(text));
}

bool shoots(const pool_ShotOption& option) {
  const std::int32_t value = rawValue(option);
  return value != pool_OPTION_REBREAK && value != pool_OPTION_OPPONENT_REBREAKS &&
         value != pool_OPTION_PASS_BACK && value != pool_OPTION_REPLACE;
}

/// Printable ASCII without spaces; empty passes (an empty pocket name means none).
bool printable(std::string_view text) {
  return std::all_of(text.begin(), text.end(), [](char c) { return c > ' ' && c < 127; });
}

Check checkIdentity(const pool_ShotCommand& c) {
  if (CommandCheck check = checkMatchAndSeat(c); !check) return check;
  return std::nullopt;
}

Check checkFinite(const pool_ShotCommand& c) {
  const std::pair<const char*, double> numbers[] = {{"yaw", c.yaw},
                                                    {"tip_side", c.tip_side},
                                                    {"tip_height", c.tip_height},
                                                    {"elevation", c.elevation},
                                                    {"speed", c.speed},
                                                    {"cue_ball_x", c.cue_ball_x},
                                                    {"cue_ball_y", c.cue_ball_y}};
  for (const auto& [name, value] : numbers) {
    if (!std::isfinite(value)) {
      return fail(CommandProblem::NonFinite, std::string(name) + ": must be a finite number");
    }
  }
  return std::nullopt;
}

Check checkOption(const pool_ShotCommand& c) {
  // The enum arrives as an integer: anything outside the declared values is malformed.
  const std::int32_t value = rawValue(c.option);
  if (value < pool_OPTION_NONE || value > pool_OPTION_REPLACE) {
    return fail(CommandProblem::BadOption, "option: not a known shot option");
  }
  return std::nullopt;
}

CommandProblem problemOf(physics::ShotProblem problem) {
  switch (problem) {
    case physics::ShotProblem::None:
      return CommandProblem::None;
    case physics::ShotProblem::NonFinite:
      return CommandProblem::NonFinite;
    case physics::ShotProblem::SpeedOutOfRange:
      return CommandProblem::SpeedOutOfRange;
    case physics::ShotProblem::ElevationOutOfRange:
      return CommandProblem::ElevationOutOfRange;
    case physics::ShotProblem::TipOutOfRange:
      return CommandProblem::TipOutOfRange;
    case physics::ShotProblem::YawOutOfRange:
      return CommandProblem::YawOutOfRange;
  }
  return CommandProblem::NonFinite;
}

Check checkCue(const pool_ShotCommand& c, const protocol::CommandLimits& limits) {
  auto ok =
      physics::checkShotRange({c.speed, c.elevation, c.tip_side, c.tip_height, c.yaw}, limits);
  if (!ok) return fail(problemOf(ok.code()), ok.error());
  return std::nullopt;
}

Check checkCall(const pool_ShotCommand& c) {
  const bool has_ball = c.called_ball != -1;
  if (has_ball && (c.called_ball < 1 || c.called_ball > physics::kMaxBallId)) {
    return fail(CommandProblem::BadCall, "called_ball: must be 1-21, or -1 for none");
  }
  const std::string_view pocket = textOf(c.called_pocket);
  if (!terminated(c.called_pocket) || !printable(pocket)) {
    return fail(CommandProblem::BadCall, "called_pocket: must be a printable pocket name");
  }
  // A ball alone is snooker's nominated ball; a pool game's rules refuse a call without a pocket.
  if (!has_ball && !pocket.empty()) {
    return fail(CommandProblem::BadCall, "called_pocket: needs a called_ball");
  }
  return std::nullopt;
}

Check checkPlacement(const pool_ShotCommand& c, const protocol::CommandLimits& limits) {
  if (c.has_cue_ball_placement &&
      (std::abs(c.cue_ball_x) > limits.half_length || std::abs(c.cue_ball_y) > limits.half_width)) {
    return fail(CommandProblem::PlacementOutOfRange, "cue_ball_x, cue_ball_y: off the table");
  }
  return std::nullopt;
}

Check checkSignature(const pool_ShotCommand& c) {
  if (c.signature._length > 64 || (c.signature._length > 0 && !c.signature._buffer)) {
    return fail(CommandProblem::BadSignature, "signature: at most 64 bytes");
  }
  return std::nullopt;
}

}  // namespace

const char* toString(CommandProblem problem) {
  switch (problem) {
    case CommandProblem::None:
      return "none";
    case CommandProblem::BadMatchId:
      return "bad_match_id";
    case CommandProblem::BadSeat:
      return "bad_seat";
    case CommandProblem::NonFinite:
      return "non_finite";
    case CommandProblem::BadOption:
      return "bad_option";
    case CommandProblem::SpeedOutOfRange:
      return "speed_out_of_range";
    case CommandProblem::ElevationOutOfRange:
      return "elevation_out_of_range";
    case CommandProblem::TipOutOfRange:
      return "tip_out_of_range";
    case CommandProblem::YawOutOfRange:
      return "yaw_out_of_range";
    case CommandProblem::BadCall:
      return "bad_call";
    case CommandProblem::PlacementOutOfRange:
      return "placement_out_of_range";
    case CommandProblem::BadSignature:
      return "bad_signature";
  }
  return "unknown";
}

CommandCheck validateShotCommand(const pool_ShotCommand& command,
                                 const protocol::CommandLimits& limits) {
  // In CommandProblem's order; the first problem found is the one reported.
  Check found = checkIdentity(command);
  if (!found) found = checkFinite(command);
  if (!found) found = checkOption(command);
  if (!found && shoots(command.option)) found = checkCue(command, limits);
  if (!found) found = checkCall(command);
  if (!found) found = checkPlacement(command, limits);
  if (!found) found = checkSignature(command);
  return found.value_or(CommandCheck::pass());
}

IncomingCommand readCommand(const pool_ShotCommand& command,
                            const protocol::CommandLimits& limits) {
  IncomingCommand in;
  in.match = std::string(textOf(command.match));
  in.seat = command.seat;
  in.seq = command.seq;
  const CommandCheck check = validateShotCommand(command, limits);
  auto request = check ? fromWire(command) : Result<protocol::ShotRequest>::fail(check.error());
  if (request) {
    in.request = std::move(*request);
  } else {
    in.bad_signature = check.code() == CommandProblem::BadSignature;
    in.problem = request.error();
  }
  return in;
}

bool printableId(std::string_view text) {
  return !text.empty() && printable(text);
}

}  // namespace pool::net
