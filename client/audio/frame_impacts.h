// Impacts read off consecutive table frames, for shots whose event log is not known yet.
#pragma once

#include <array>
#include <vector>

#include "physics/ball.h"
#include "physics/events.h"

namespace pool::audio {

struct FrameImpactOptions {
  double ball_radius = 0.028575;  ///< m
  /// m/s: a velocity change beyond what the cloth can do in one frame (μ g dt, μ ≤ 0.25) plus
  /// this is an impact.
  double min_dv = 0.05;
  double cushion_restitution = 0.75;  ///< to turn a rebound's Δv into the impact speed
  double max_gap = 0.25;              ///< s: frames further apart than this are not compared
};

/// Infers the sounding events of a shot (strike, ball–ball, cushion, pocket) from its 60 Hz frames
/// (positions, velocities, states). A ball–ball contact gets its time and closing speed from the
/// two balls' straight paths between the frames, as the physics defines them (a ball jolted while
/// touching a jolted one, as in a rack, was hit at the speed it left with); a rebound off a
/// cushion gets Δv / (1 + e) half a frame back. Approximate by nature, but in time with the
/// picture: the server sends a shot's exact event log only after its last frame.
class FrameImpacts {
 public:
  explicit FrameImpacts(const FrameImpactOptions& options = {});

  /// Forgets the previous frame (a new shot).
  void reset();

  /// The events between the previous frame and this one (`sim_time` s since the strike), in
  /// time order. The first frame of a shot gives the strike only when it is the strike's own
  /// frame; a frame out of order gives nothing.
  physics::EventLog onFrame(const std::vector<physics::Ball>& balls, double sim_time);

 private:
  struct Seen {
    physics::Vec3 pos = physics::Vec3::Zero();
    physics::Vec3 vel = physics::Vec3::Zero();
    physics::MotionState state = physics::MotionState::Stationary;
    bool present = false;
  };
  using Table = std::array<Seen, physics::kMaxBallId + 1>;

  /// Contact time (s after the previous frame) of balls a and b moving straight, if within dt.
  bool contactTime(const Seen& a, const Seen& b, double dt, double& tau) const;
  /// Ball–ball events among the balls of `hit` (their velocity jumped by `jolt`, m/s): pairs
  /// whose straight paths met between the frames, then balls that touched a jolted one.
  void pairs(const std::vector<int>& hit, const std::vector<double>& jolt, double dt,
             physics::EventLog& out, std::vector<bool>& paired) const;

  FrameImpactOptions options_;
  Table prev_{};
  double prev_t_ = 0.0;
  bool have_prev_ = false;
};

}  // namespace pool::audio
