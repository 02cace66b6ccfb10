// The critically damped glide of each of the cue's values toward the latest relayed aim.
#include "client/app/aim_follower.h"

#include <cmath>
#include <numbers>

namespace pool::app {
namespace {

/// The target values of `s` in the axes' order; the heading is unwrapped next to `near`.
void targets(const protocol::AimSample& s, double near_yaw, double (&out)[7]) {
  out[0] = near_yaw + angleBetween(s.yaw, near_yaw);
  out[1] = s.tip_side;
  out[2] = s.tip_height;
  out[3] = s.elevation;
  out[4] = s.power;
  out[5] = s.cue_ball_x;
  out[6] = s.cue_ball_y;
}

}  // namespace

double angleBetween(double a, double b) {
  double d = std::remainder(a - b, 2.0 * std::numbers::pi);
  if (d <= -std::numbers::pi) d += 2.0 * std::numbers::pi;
  return d;
}

void AimFollower::receive(const protocol::AimSample& sample, double now) {
  const bool fresh = !target_ || target_->seat != sample.seat ||
                     target_->shot_number != sample.shot_number || stroked_ ||
                     now - received_at_ > stale_;
  target_ = sample;
  received_at_ = now;
  if (fresh) {
    stroked_ = false;
    double t[kAxes];
    targets(sample, sample.yaw, t);
    for (int i = 0; i < kAxes; ++i) axes_[i] = Axis{t[i], 0.0};
    now_ = now;
  }
  if (sample.stroke && !stroked_) {
    stroked_ = true;
    FollowedAim f;
    f.seat = sample.seat;
    f.shot_number = sample.shot_number;
    f.aim.yaw = sample.yaw;
    f.aim.tip_side = sample.tip_side;
    f.aim.tip_height = sample.tip_height;
    f.aim.elevation = sample.elevation;
    f.aim.power = sample.power;
    f.cue_ball = {sample.cue_ball_x, sample.cue_ball_y};
    stroke_ = f;
  }
}

void AimFollower::advance(double now) {
  if (!target_) return;
  const double dt = now - now_;
  now_ = now;
  if (!(dt > 0.0)) return;
  double t[kAxes];
  targets(*target_, axes_[0].x, t);
  // The exact step of x'' = -2w x' - w^2 (x - target) over dt (no overshoot, any dt).
  const double w = rate_;
  const double decay = std::exp(-w * dt);
  for (int i = 0; i < kAxes; ++i) {
    Axis& a = axes_[i];
    const double d = a.x - t[i];
    const double k = a.v + w * d;
    a.x = t[i] + (d + k * dt) * decay;
    a.v = (a.v - w * k * dt) * decay;
  }
}

std::optional<FollowedAim> AimFollower::shown() const {
  if (!target_ || stroked_ || now_ - received_at_ > stale_) return std::nullopt;
  FollowedAim f;
  f.seat = target_->seat;
  f.shot_number = target_->shot_number;
  f.aim.yaw = angleBetween(axes_[0].x, 0.0);
  f.aim.tip_side = axes_[1].x;
  f.aim.tip_height = axes_[2].x;
  f.aim.elevation = axes_[3].x;
  f.aim.power = axes_[4].x;
  f.cue_ball = {axes_[5].x, axes_[6].x};
  return f;
}

std::optional<FollowedAim> AimFollower::takeStroke() {
  auto out = std::move(stroke_);
  stroke_.reset();
  return out;
}

void AimFollower::forget() {
  target_.reset();
  stroke_.reset();
  stroked_ = false;
}

}  // namespace pool::app
