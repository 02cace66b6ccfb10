// Cue strike: a frictionless point impulse along the cue (Alciatore TP A-30), squirt per TP A-31.
#include "physics/cue_strike.h"

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "physics/shot_limits.h"

namespace pool::physics {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;
// Offsets are compared with the limit after a square root; allow for its rounding so that
// exactly the limit (e.g. 0.3, 0.4 against 0.5) stays legal.
constexpr double kOffsetTolerance = 1e-12;

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// Unit vectors of the cue: d along the cue (toward the ball, tilted down by the elevation),
/// right (horizontal, right of the cue seen from behind) and up (perpendicular to both).
struct CueFrame {
  Vec3 d, right, up;
};

CueFrame cueFrame(double yaw, double elevation) {
  CueFrame f;
  f.d = Vec3(std::cos(elevation) * std::cos(yaw), std::cos(elevation) * std::sin(yaw),
             -std::sin(elevation));
  f.right = Vec3(std::sin(yaw), -std::cos(yaw), 0.0);
  f.up = f.right.cross(f.d);
  return f;
}

}  // namespace

std::string validateShot(const CueShot& shot, const table::PhysicsParams& params) {
  if (!std::isfinite(shot.yaw)) return "yaw_deg: must be a finite number";
  if (!std::isfinite(shot.tip_side)) return "tip_side: must be a finite number";
  if (!std::isfinite(shot.tip_height)) return "tip_height: must be a finite number";
  if (!std::isfinite(shot.elevation) || shot.elevation < 0.0 ||
      shot.elevation / kDeg > kMaxElevationDeg + 1e-9) {
    return "elevation_deg: must be a finite number in [0, " + fmt(kMaxElevationDeg) + "]";
  }
  if (!std::isfinite(shot.speed) || shot.speed <= 0.0 || shot.speed > kMaxShotSpeed) {
    return "speed: must be a finite number in (0, " + fmt(kMaxShotSpeed) + "]";
  }
  const double offset = std::hypot(shot.tip_side, shot.tip_height);
  if (offset > params.miscue_limit + kOffsetTolerance) {
    return "tip_side: tip offset " + fmt(offset) + " R is beyond the miscue limit " +
           fmt(params.miscue_limit) + " R (a miscue)";
  }
  return {};
}

Result<StrikeOutcome> strikeCueBall(const CueShot& shot, const table::PhysicsParams& params) {
  if (auto reason = validateShot(shot, params); !reason.empty()) {
    return Result<StrikeOutcome>::fail(reason);
  }
  const double m = params.ball_mass;
  const double R = params.ball_radius;
  const double a = shot.tip_side;
  const double b = shot.tip_height;
  const double off2 = std::min(1.0, a * a + b * b);
  const CueFrame f = cueFrame(shot.yaw, shot.elevation);

  // Where the cue's line first meets the sphere, relative to the centre.
  const Vec3 r = R * (a * f.right + b * f.up - std::sqrt(1.0 - off2) * f.d);

  // Impulse along the cue: J = 2 m V0 / (1 + m/M + 2.5 (a² + b²)); in "ball" mode scaled so
  // the ball leaves at the requested speed.
  const double J = shot.speed_is_ball
                       ? m * shot.speed
                       : 2.0 * m * shot.speed / (1.0 + m / params.cue_mass + 2.5 * off2);
  const double inertia = 0.4 * m * R * R;

  StrikeOutcome out;
  out.vel = (J / m) * f.d;
  out.ang_vel = r.cross(J * f.d) / inertia;

  // Squirt turns the heading away from the side struck (right English → left), cue mode only.
  if (!shot.speed_is_ball) {
    const double mr = m / params.cue_end_mass;
    out.squirt = std::atan(2.5 * a * std::sqrt(std::max(0.0, 1.0 - a * a)) /
                           (1.0 + mr + 2.5 * (1.0 - a * a)));
    const Eigen::AngleAxisd turn(out.squirt, Vec3::UnitZ());
    out.vel = turn * out.vel;
  }
  return Result<StrikeOutcome>::ok(out);
}

}  // namespace pool::physics
