// The other shooter's cue as a viewer draws it: each relayed aim is a target the drawn cue glides
// to, critically damped (no overshoot, heading wrapped the short way round), hidden when no fresh
// aim came for a while; a stroke is handed out once. Pure: time passes only through `now`.
#pragma once

#include <cstdint>
#include <optional>

#include "client/app/aim.h"
#include "protocol/aim_sample.h"

namespace pool::app {

/// The cue of a remote shooter, as drawn now.
struct FollowedAim {
  int seat = -1;
  std::uint32_t shot_number = 0;
  AimState aim;  ///< yaw, tip, elevation and power (smoothed); no call or placement
  Eigen::Vector2d cue_ball = Eigen::Vector2d::Zero();  ///< smoothed too (a ball in hand moves)
};

class AimFollower {
 public:
  /// `rate` (1/s): how quickly the drawn cue closes on the latest aim (critically damped: 99 %
  /// of a step after 6.6/rate s). `stale` (s): hidden after this long without an aim.
  explicit AimFollower(double rate = 25.0, double stale = 1.0) : rate_(rate), stale_(stale) {}

  /// A relayed aim arrived at `now` (s). A new shooter or turn starts from it, without a glide.
  void receive(const protocol::AimSample& sample, double now);
  /// Advances the glide to `now`.
  void advance(double now);
  /// The cue to draw at the last advance: empty before the first aim, once the aim is stale, after
  /// a stroke or forget().
  std::optional<FollowedAim> shown() const;
  /// The aim the last stroke was released with (its power), handed out once.
  std::optional<FollowedAim> takeStroke();
  /// The turn is over, or the shooter is no longer followed: nothing is drawn until a new aim.
  void forget();

  /// The latest aim received (unsmoothed), for the HUD's numbers and the tests.
  const std::optional<protocol::AimSample>& latest() const { return target_; }

 private:
  /// One smoothed value and its rate of change.
  struct Axis {
    double x = 0.0;
    double v = 0.0;
  };
  static constexpr int kAxes = 7;  ///< yaw, side, height, elevation, power, x, y

  double rate_;
  double stale_;
  std::optional<protocol::AimSample> target_;
  double received_at_ = 0.0;
  double now_ = 0.0;
  bool stroked_ = false;
  std::optional<FollowedAim> stroke_;
  Axis axes_[kAxes];
};

/// `a` - `b` wrapped into (-pi, pi].
double angleBetween(double a, double b);

}  // namespace pool::app
