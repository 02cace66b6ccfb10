// What must hold of validateShotCommand's verdict on any command, checked by the fuzz targets.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

#include "broken_promise.h"
#include "net/shot_command_check.h"
#include "net/wire_fields.h"
#include "physics/ball.h"

namespace pool::fuzz {

[[noreturn]] inline void violated(const char* what, const net::CommandCheck& check) {
  brokenPromise(std::string(what) + " (problem " + net::toString(check.code()) + ", text '" +
                check.error() + "')");
}

/// Checks the verdict against the header's promises: a reason iff a problem, a known problem, and
/// an accepted command whose every field is representable and within the default limits.
inline void checkVerdict(const pool_ShotCommand& c, const net::CommandCheck& check) {
  if (check.ok() != check.error().empty()) violated("a reason without a problem or back", check);
  if (std::strcmp(net::toString(check.code()), "unknown") == 0) violated("unknown problem", check);
  if (!check.ok()) return;
  const protocol::CommandLimits limits;
  const auto match = net::textOf(c.match);
  const bool printable =
      std::all_of(match.begin(), match.end(), [](char ch) { return ch > ' ' && ch < 127; });
  if (!net::terminated(c.match) || match.empty() || !printable)
    violated("accepted a bad match id", check);
  if (c.seat != 0 && c.seat != 1) violated("accepted a bad seat", check);
  for (const double v :
       {c.yaw, c.tip_side, c.tip_height, c.elevation, c.speed, c.cue_ball_x, c.cue_ball_y}) {
    if (!std::isfinite(v)) violated("accepted a non-finite number", check);
  }
  const std::int32_t option = net::rawValue(c.option);
  if (option < pool_OPTION_NONE || option > pool_OPTION_REPLACE) {
    violated("accepted an unknown option", check);
  }
  // Re-racks, passing the table back and snooker's balls put back are choices without a shot:
  // no cue to check.
  const bool shoots = option != pool_OPTION_REBREAK && option != pool_OPTION_OPPONENT_REBREAKS &&
                      option != pool_OPTION_PASS_BACK && option != pool_OPTION_REPLACE;
  constexpr double tol = physics::kRangeTolerance;  // exactly a limit is legal, give or take this
  if (shoots &&
      (c.speed <= 0.0 || c.speed > limits.max_speed || c.elevation < 0.0 ||
       c.elevation > limits.max_elevation + tol || std::abs(c.yaw) > limits.max_abs_yaw + tol ||
       std::hypot(c.tip_side, c.tip_height) > limits.miscue_limit + tol)) {
    violated("accepted a shot out of range", check);
  }
  const bool has_ball = c.called_ball != -1;
  if (has_ball && (c.called_ball < 1 || c.called_ball > physics::kMaxBallId)) {
    violated("accepted a bad ball", check);
  }
  // A ball alone is snooker's nomination; a pocket needs a ball.
  if (!net::terminated(c.called_pocket) || (!has_ball && !net::textOf(c.called_pocket).empty())) {
    violated("accepted a bad call", check);
  }
  if (c.has_cue_ball_placement &&
      (std::abs(c.cue_ball_x) > limits.half_length || std::abs(c.cue_ball_y) > limits.half_width)) {
    violated("accepted a placement off the table", check);
  }
  if (c.signature._length > 64 || (c.signature._length > 0 && c.signature._buffer == nullptr)) {
    violated("accepted a bad signature", check);
  }
}

}  // namespace pool::fuzz
