// The one check of a cue shot's values against their ranges (shot_limits.h).
#include "physics/shot_limits.h"

#include <cmath>
#include <cstdio>
#include <string>

namespace pool::physics {
namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

std::string number(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

Check<ShotProblem> refuse(ShotProblem problem, std::string sentence) {
  return Check<ShotProblem>::refuse(problem, std::move(sentence));
}

}  // namespace

const char* toString(ShotProblem problem) {
  switch (problem) {
    case ShotProblem::None:
      return "none";
    case ShotProblem::NonFinite:
      return "non_finite";
    case ShotProblem::SpeedOutOfRange:
      return "speed_out_of_range";
    case ShotProblem::ElevationOutOfRange:
      return "elevation_out_of_range";
    case ShotProblem::TipOutOfRange:
      return "tip_out_of_range";
    case ShotProblem::YawOutOfRange:
      return "yaw_out_of_range";
  }
  return "unknown";
}

Check<ShotProblem> checkShotRange(const ShotValues& v, const ShotRanges& r, bool with_speed) {
  const std::pair<const char*, double> values[] = {{"speed", with_speed ? v.speed : 0.0},
                                                   {"elevation", v.elevation},
                                                   {"tip_side", v.tip_side},
                                                   {"tip_height", v.tip_height},
                                                   {"yaw", v.yaw}};
  for (const auto& [name, value] : values) {
    if (!std::isfinite(value))
      return refuse(ShotProblem::NonFinite, std::string(name) + ": must be a finite number");
  }
  if (with_speed && !(v.speed > 0.0 && v.speed <= r.max_speed)) {
    return refuse(ShotProblem::SpeedOutOfRange,
                  "speed: must be in (0, " + number(r.max_speed) + "] m/s");
  }
  if (!(v.elevation >= 0.0 && v.elevation <= r.max_elevation + kRangeTolerance)) {
    return refuse(ShotProblem::ElevationOutOfRange,
                  "elevation: must be in [0, " + number(r.max_elevation / kDeg) + "] degrees");
  }
  const double offset = std::hypot(v.tip_side, v.tip_height);
  if (offset > r.miscue_limit + kRangeTolerance) {
    return refuse(ShotProblem::TipOutOfRange, "tip_side, tip_height: offset " + number(offset) +
                                                  " R is beyond the miscue limit " +
                                                  number(r.miscue_limit) + " R");
  }
  if (std::abs(v.yaw) > r.max_abs_yaw + kRangeTolerance) {
    return refuse(ShotProblem::YawOutOfRange,
                  "yaw: must be at most " + number(r.max_abs_yaw / kDeg) + " degrees either way");
  }
  return Check<ShotProblem>::pass();
}

}  // namespace pool::physics
