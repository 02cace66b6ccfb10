// A ball's state (pose, velocities, motion state) as the physics reports it.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace pool::physics {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;
using Quat = Eigen::Quaterniond;

constexpr double kGravity = 9.81;  ///< m/s²
constexpr int kCueBall = 0;
/// The highest ball id: a snooker set (the cue ball, 15 reds and six colours; pool uses 0–15).
constexpr int kMaxBallId = 21;

/// What a ball is doing. Stationary: no motion. Spinning: in place about the vertical. Sliding:
/// its contact point slips on the cloth. Rolling: no slip. Airborne: off the slate. Pocketed: in a
/// pocket or the trough. OffTable: left the table.
enum class MotionState : std::uint8_t {
  Stationary,
  Spinning,
  Sliding,
  Rolling,
  Airborne,
  Pocketed,
  OffTable,
};

const char* toString(MotionState state);
std::optional<MotionState> motionStateFromString(std::string_view name);

/// True while a ball is still on the table (not pocketed, not off the table).
inline bool onTable(MotionState s) {
  return s != MotionState::Pocketed && s != MotionState::OffTable;
}

/// One ball. Table frame (origin at the centre of the slate surface, +x toward the foot spot,
/// +z up), SI units; a ball at rest on the slate has pos.z() == R.
struct Ball {
  int id = 0;
  Vec3 pos = Vec3::Zero();
  Quat orient = Quat::Identity();
  Vec3 vel = Vec3::Zero();      ///< m/s
  Vec3 ang_vel = Vec3::Zero();  ///< rad/s
  MotionState state = MotionState::Stationary;
  std::string pocket;  ///< the pocket's name once pocketed
};

/// A ball at rest on the slate with its centre above `at` (table plane, m).
inline Ball restingBall(int id, const Vec2& at, double radius) {
  Ball b;
  b.id = id;
  b.pos = Vec3(at.x(), at.y(), radius);
  return b;
}

}  // namespace pool::physics
