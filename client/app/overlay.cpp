// Overlay segments from the aim and the balls' motion (the cue itself is a 3-D model).
#include "client/app/overlay.h"

#include <cmath>
#include <numbers>

namespace pool::app {
namespace {

const Eigen::Vector3d kAimColour(1.0, 1.0, 1.0);
const Eigen::Vector3d kObjectColour(1.0, 0.85, 0.2);
const Eigen::Vector3d kBankColour(0.55, 0.8, 1.0);
const Eigen::Vector3d kCueColour(0.75, 0.55, 0.3);
const Eigen::Vector3d kVelocityColour(0.2, 0.9, 1.0);
const Eigen::Vector3d kSpinColour(1.0, 0.3, 0.8);

constexpr double kVelocitySeconds = 0.25;  // velocity arrows show this much travel
constexpr double kSpinScale = 0.004;       // m per rad/s
constexpr double kObjectLine = 0.4;        // m of the object ball's heading drawn

Eigen::Vector3d at(const Eigen::Vector2d& p, double z) {
  return {p.x(), p.y(), z};
}

}  // namespace

std::vector<OverlaySegment> aimOverlay(const AimPrediction& aim, double radius) {
  std::vector<OverlaySegment> out;
  out.push_back({at(aim.from, radius), at(aim.contact, radius), kAimColour});
  if (aim.ball) {
    const Eigen::Vector2d object = aim.contact + 2 * radius * aim.object_dir;
    out.push_back(
        {at(object, radius), at(object + kObjectLine * aim.object_dir, radius), kObjectColour});
  }
  return out;
}

std::vector<OverlaySegment> bankOverlay(const BankPath& path, double radius) {
  std::vector<OverlaySegment> out;
  // The first leg is the aim line's own (aimOverlay draws it).
  for (std::size_t i = 2; i < path.points.size(); ++i) {
    out.push_back({at(path.points[i - 1], radius), at(path.points[i], radius), kBankColour});
  }
  return out;
}

std::vector<OverlaySegment> motionOverlay(const std::vector<physics::Ball>& balls) {
  std::vector<OverlaySegment> out;
  for (const auto& b : balls) {
    if (!physics::onTable(b.state)) continue;
    if (b.vel.squaredNorm() > 1e-8)
      out.push_back({b.pos, b.pos + b.vel * kVelocitySeconds, kVelocityColour});
    if (b.ang_vel.squaredNorm() > 1e-4)
      out.push_back({b.pos, b.pos + b.ang_vel * kSpinScale, kSpinColour});
  }
  return out;
}

std::vector<OverlaySegment> cueDirectionOverlay(const Eigen::Vector3d& cue_ball, double yaw) {
  const Eigen::Vector3d dir(std::cos(yaw), std::sin(yaw), 0.0);
  return {{cue_ball, cue_ball + 0.3 * dir, kCueColour}};
}

std::vector<OverlaySegment> ringOverlay(const Eigen::Vector2d& centre, double radius, double z,
                                        const Eigen::Vector3d& colour) {
  constexpr int kSides = 32;
  std::vector<OverlaySegment> out;
  const auto at = [&](int i) {
    const double t = 2 * std::numbers::pi * i / kSides;
    return Eigen::Vector3d(centre.x() + radius * std::cos(t), centre.y() + radius * std::sin(t), z);
  };
  for (int i = 0; i < kSides; ++i) out.push_back({at(i), at(i + 1), colour});
  return out;
}

}  // namespace pool::app
