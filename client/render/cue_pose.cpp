// Cue placement: the physics' strike frame, the draw-back and the clearance search.
#include "client/render/cue_pose.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "client/render/cue_profile.h"
#include "physics/shot_limits.h"

namespace pool::render {

namespace {

constexpr float kClearance = 0.002f;     // m kept between the cue and what it passes over
constexpr float kStepRad = 0.00872665f;  // 0.5°
constexpr auto kMaxElevationRad = static_cast<float>(physics::kMaxElevation);
constexpr float kSampleStep = 0.005f;  // m between the cue's checked points

/// The cue's radius at each checked point s = i · kSampleStep from the tip, m (made once).
const std::vector<float>& sampleRadii() {
  static const std::vector<float> radii = [] {
    std::vector<float> r;
    for (double along = 0.0; along <= cueLength(); along += kSampleStep) {
      r.push_back(static_cast<float>(cueRadiusAt(along)));
    }
    return r;
  }();
  return radii;
}

/// True when the cue's cross-section of radius `r` at `p` stays above the cushions and rails.
bool clearOfRails(const glm::vec3& p, float r, const CueObstacles& o) {
  // The rail band widened by the step between samples, so no stretch of cue slips through.
  const float over_x = std::abs(p.x) - (o.half_length - r - kSampleStep);
  const float over_y = std::abs(p.y) - (o.half_width - r - kSampleStep);
  const bool over_rail = (over_x > 0.0f || over_y > 0.0f) &&
                         std::abs(p.x) < o.half_length + o.rail_outer + r &&
                         std::abs(p.y) < o.half_width + o.rail_outer + r;
  return !over_rail || p.z - r >= o.rail_top + kClearance;
}

/// True when the cue's surface keeps clear of every ball: each ball against the nearest point of
/// the cue's axis, with the cue's radius there.
bool clearOfBalls(const glm::vec3& tip, const glm::vec3& forward, const CueObstacles& o) {
  const auto& radii = sampleRadii();
  const float length = kSampleStep * static_cast<float>(radii.size() - 1);
  return std::none_of(o.balls.begin(), o.balls.end(), [&](const glm::vec3& b) {
    const float s = std::clamp(glm::dot(tip - b, forward), 0.0f, length);
    const float r = radii[static_cast<std::size_t>(std::lround(s / kSampleStep))];
    const float reach = o.ball_radius + r + kClearance;
    const glm::vec3 d = tip - forward * s - b;
    return glm::dot(d, d) < reach * reach;
  });
}

/// True when the whole cue, tip at `tip` and pointing along `forward`, is clear.
bool cueClear(const glm::vec3& tip, const glm::vec3& forward, const CueObstacles& o) {
  if (!clearOfBalls(tip, forward, o)) return false;
  const auto& radii = sampleRadii();
  for (std::size_t i = 0; i < radii.size(); ++i) {
    const float s = kSampleStep * static_cast<float>(i);
    if (!clearOfRails(tip - forward * s, radii[i], o)) return false;
  }
  return true;
}

}  // namespace

glm::vec3 cueDirection(float yaw, float elevation) {
  return {std::cos(elevation) * std::cos(yaw), std::cos(elevation) * std::sin(yaw),
          -std::sin(elevation)};
}

glm::vec3 struckPoint(const CueAim& aim, float radius) {
  const glm::vec3 d = cueDirection(aim.yaw, aim.elevation);
  const glm::vec3 right(std::sin(aim.yaw), -std::cos(aim.yaw), 0.0f);
  const glm::vec3 up = glm::cross(right, d);
  const float a = aim.tip_side, b = aim.tip_height;
  const float off2 = std::min(1.0f, a * a + b * b);
  return aim.cue_ball + radius * (a * right + b * up - std::sqrt(1.0f - off2) * d);
}

CuePlacement placeCue(const CueAim& aim, const CueObstacles& obstacles) {
  const glm::vec3 struck = struckPoint(aim, obstacles.ball_radius);
  const float draw_back = std::clamp(aim.power, kFollowThrough, 1.0f) * kMaxDrawBack;
  // Drawn back along its own (possibly raised) line, as a player's stroke is.
  const auto at = [&](float elevation) {
    CuePlacement p;
    p.drawn_elevation = elevation;
    p.forward = cueDirection(aim.yaw, elevation);
    p.tip = struck - p.forward * draw_back;
    p.butt = p.tip - p.forward * static_cast<float>(cueLength());
    return p;
  };
  CuePlacement out = at(std::clamp(aim.elevation, 0.0f, kMaxElevationRad));
  while (out.drawn_elevation < kMaxElevationRad && !cueClear(out.tip, out.forward, obstacles)) {
    out = at(std::min(out.drawn_elevation + kStepRad, kMaxElevationRad));
  }
  return out;
}

float strokePower(float released, float seconds) {
  if (!(seconds >= 0.0f) || seconds > kStrokeEnd) return std::numeric_limits<float>::quiet_NaN();
  const float t = std::min(seconds / kStrokeForward, 1.0f);
  // Accelerating through the ball, as a stroke does: the draw-back closes as 1 − t².
  return released + (kFollowThrough - released) * t * t;
}

float cueOpacity(const CuePlacement& cue, glm::vec3 eye) {
  const glm::vec3 axis = cue.butt - cue.tip;
  const float t = std::clamp(glm::dot(eye - cue.tip, axis) / glm::dot(axis, axis), 0.0f, 1.0f);
  const float distance = glm::length(eye - (cue.tip + t * axis));
  return std::clamp((distance - 0.03f) / 0.06f, 0.3f, 1.0f);
}

}  // namespace pool::render
