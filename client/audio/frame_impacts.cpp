// Reads impacts off velocity jumps between frames: pairs of balls, cushions, drops into pockets.
#include "client/audio/frame_impacts.h"

#include <algorithm>
#include <cmath>

namespace pool::audio {

using physics::Event;
using physics::EventType;
using physics::MotionState;

FrameImpacts::FrameImpacts(const FrameImpactOptions& options) : options_(options) {}

void FrameImpacts::reset() {
  prev_ = Table{};
  have_prev_ = false;
}

bool FrameImpacts::contactTime(const Seen& a, const Seen& b, double dt, double& tau) const {
  // |dp + dv τ| = 2R, the earliest root in [0, dt] while closing.
  const physics::Vec3 dp = b.pos - a.pos;
  const physics::Vec3 dv = b.vel - a.vel;
  const double d = 2.0 * options_.ball_radius;
  const double qa = dv.squaredNorm();
  const double qb = 2.0 * dp.dot(dv);
  const double qc = dp.squaredNorm() - d * d;
  if (qc <= 0.0) {
    tau = 0.0;  // touching already (a rack): the contact is now
    return qb < 0.0;
  }
  const double disc = qb * qb - 4.0 * qa * qc;
  if (qa <= 0.0 || disc < 0.0) return false;
  tau = (-qb - std::sqrt(disc)) / (2.0 * qa);
  return tau >= 0.0 && tau <= dt;
}

void FrameImpacts::pairs(const std::vector<int>& hit, const std::vector<double>& jolt, double dt,
                         physics::EventLog& out, std::vector<bool>& paired) const {
  auto add = [&](int a, int b, double t, double speed, const physics::Vec3& pos) {
    Event e;
    e.t = t;
    e.type = EventType::BallBall;
    e.ball_a = a;
    e.ball_b = b;
    e.speed = speed;
    e.pos = pos;
    out.push_back(e);
  };
  // First, pairs whose straight paths meet: time and closing speed as the physics defines them.
  for (std::size_t i = 0; i < hit.size(); ++i) {
    for (std::size_t j = i + 1; j < hit.size() && !paired[i]; ++j) {
      if (paired[j]) continue;
      const Seen& a = prev_[static_cast<std::size_t>(hit[i])];
      const Seen& b = prev_[static_cast<std::size_t>(hit[j])];
      double tau = 0.0;
      if (!contactTime(a, b, dt, tau)) continue;
      const physics::Vec3 n = ((b.pos + b.vel * tau) - (a.pos + a.vel * tau)).normalized();
      const double speed = (a.vel - b.vel).dot(n);
      if (!(speed > 0.0)) continue;
      add(hit[i], hit[j], prev_t_ + tau, speed, a.pos + a.vel * tau);
      paired[i] = paired[j] = true;
    }
  }
  // Then chains inside one frame (a rack): a jolted ball that touched another jolted one was hit
  // by it, at about the speed it left with (equal masses, e ≈ 1).
  const double touch = 2.0 * options_.ball_radius + 0.003;
  for (std::size_t i = 0; i < hit.size(); ++i) {
    for (std::size_t j = 0; j < hit.size() && !paired[i]; ++j) {
      const Seen& a = prev_[static_cast<std::size_t>(hit[i])];
      const Seen& b = prev_[static_cast<std::size_t>(hit[j])];
      if (i == j || (a.pos - b.pos).norm() > touch) continue;
      add(hit[j], hit[i], prev_t_ + 0.5 * dt, jolt[i], 0.5 * (a.pos + b.pos));
      paired[i] = true;
    }
  }
}

physics::EventLog FrameImpacts::onFrame(const std::vector<physics::Ball>& balls, double sim_time) {
  Table now{};
  for (const auto& b : balls) {
    if (b.id < 0 || b.id > physics::kMaxBallId) continue;
    now[static_cast<std::size_t>(b.id)] = {b.pos, b.vel, b.state, true};
  }
  physics::EventLog out;
  const bool first = !have_prev_;
  const double dt = sim_time - prev_t_;
  if (!std::isfinite(sim_time) || (!first && dt <= 0.0)) return out;
  if (first) {
    // The strike's own frame: the cue ball already moving at t ≈ 0.
    const Seen& cue = now[physics::kCueBall];
    if (cue.present && sim_time < 0.5 / 60.0 && cue.vel.norm() > options_.min_dv) {
      Event e;
      e.t = 0.0;
      e.type = EventType::Strike;
      e.speed = cue.vel.norm();
      e.pos = cue.pos;
      out.push_back(e);
    }
  } else if (dt <= options_.max_gap) {
    // Drops into pockets, and the balls whose velocity jumped beyond the cloth's doing.
    const double cloth = 0.25 * physics::kGravity * dt;
    std::vector<int> hit;
    std::vector<double> jolt;  // |Δv| of each ball of `hit`
    for (int id = 0; id <= physics::kMaxBallId; ++id) {
      const Seen& a = prev_[static_cast<std::size_t>(id)];
      const Seen& b = now[static_cast<std::size_t>(id)];
      if (!a.present || !b.present) continue;
      if (physics::onTable(a.state) && b.state == MotionState::Pocketed) {
        Event e;
        e.t = sim_time - 0.5 * dt;
        e.type = EventType::Pocket;
        e.ball_a = id;
        e.pos = b.pos;
        out.push_back(e);
        continue;
      }
      // Off the table, or in the air (gravity is no impact; landings are not read off frames).
      if (!physics::onTable(b.state) || a.state == MotionState::Airborne ||
          b.state == MotionState::Airborne) {
        continue;
      }
      const double dv = (b.vel - a.vel).norm();
      if (dv > cloth + options_.min_dv) {
        hit.push_back(id);
        jolt.push_back(dv);
      }
    }
    std::vector<bool> paired(hit.size(), false);
    pairs(hit, jolt, dt, out, paired);
    // A jump with no ball to share it: a cushion or a jaw.
    for (std::size_t i = 0; i < hit.size(); ++i) {
      if (paired[i]) continue;
      const auto id = static_cast<std::size_t>(hit[i]);
      Event e;
      e.t = sim_time - 0.5 * dt;
      e.type = EventType::BallCushion;
      e.ball_a = hit[i];
      e.speed = jolt[i] / (1.0 + options_.cushion_restitution);
      e.pos = now[id].pos;
      out.push_back(e);
    }
  }
  prev_ = now;
  prev_t_ = sim_time;
  have_prev_ = true;
  std::stable_sort(out.begin(), out.end(),
                   [](const Event& a, const Event& b) { return a.t < b.t; });
  return out;
}

}  // namespace pool::audio
