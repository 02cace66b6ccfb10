// A stored shot's frames rebuilt from its layouts and event log: straight pieces between each
// ball's events, timed by the cloth's decelerations, turned as a rolling ball turns.
#include "client/app/shot_replay.h"

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <map>

namespace pool::app {
namespace {

using physics::Ball;
using physics::EventType;
using physics::MotionState;
using physics::Quat;
using physics::Vec3;

/// What a ball does after one of its knots, until the next.
enum class Phase { Rest, Slide, Roll, Air, Gone };

/// A place the log puts a ball at a time.
struct Knot {
  double t = 0.0;
  Vec3 pos = Vec3::Zero();
  Phase after = Phase::Rest;
  bool stops = false;           ///< a roll_to_rest: the piece before it ends at rest
  bool estimated = false;       ///< ball_b of a ball-ball event: placed from its own track
  Vec3 toucher = Vec3::Zero();  ///< the centre of the ball that struck it (estimated knots)
};

Phase phaseAfter(EventType type, Phase before) {
  switch (type) {
    case EventType::Strike:
    case EventType::BallBall:
    case EventType::BallCushion:
    case EventType::Land:
      return Phase::Slide;
    case EventType::SlideToRoll:
      return Phase::Roll;
    case EventType::RollToRest:
    case EventType::Respot:
      return Phase::Rest;
    case EventType::SpinToRest:
      return before;
    case EventType::Airborne:
      return Phase::Air;
    case EventType::Pocket:
    case EventType::OffTable:
      return Phase::Gone;
  }
  return before;
}

/// Where knot `i` (an estimated one) would put its ball from its own track: the knot before it
/// (resolved already), moving on linearly toward the next known knot.
Vec3 trackAt(const std::vector<Knot>& knots, std::size_t i) {
  const Knot& prev = knots[i - 1];
  if (prev.after == Phase::Rest || prev.after == Phase::Gone) return prev.pos;
  for (std::size_t j = i + 1; j < knots.size(); ++j) {
    const Knot& next = knots[j];
    if (next.estimated) continue;
    if (next.t <= prev.t) return next.pos;
    const double u = (knots[i].t - prev.t) / (next.t - prev.t);
    return (1 - u) * prev.pos + u * next.pos;
  }
  return prev.pos;
}

/// Distance along a piece of length `length` and duration `span` after `tau` s, decelerating at
/// `decel`; evenly to rest when `stops`, or when no deceleration of `decels` (tried in order) can
/// cover it still moving at its end.
double along(double length, double span, double tau, std::initializer_list<double> decels,
             bool stops) {
  if (span <= 0.0) return length;
  const double u = std::clamp(tau / span, 0.0, 1.0);
  if (!stops) {
    for (const double decel : decels) {
      const double v0 = length / span + 0.5 * decel * span;
      if (v0 - decel * span < 0.0) continue;
      return std::clamp(v0 * u * span - 0.5 * decel * u * u * span * span, 0.0, length);
    }
  }
  return length * (1.0 - (1.0 - u) * (1.0 - u));
}

struct Track {
  Ball before;
  Ball after;
  std::vector<Knot> knots;  ///< time order, the layout at the strike first
};

/// The ball's centre and phase at `t`.
std::pair<Vec3, Phase> place(const Track& track, double t, const table::PhysicsParams& params) {
  const auto& k = track.knots;
  std::size_t i = 0;
  while (i + 1 < k.size() && k[i + 1].t <= t) ++i;
  const Knot& a = k[i];
  if (i + 1 == k.size() || a.after == Phase::Rest || a.after == Phase::Gone) {
    return {a.pos, a.after};
  }
  const Knot& b = k[i + 1];
  const double span = b.t - a.t;
  const double tau = t - a.t;
  const Vec3 d = b.pos - a.pos;
  const double length = d.norm();
  if (a.after == Phase::Air) {
    const double u = span > 0 ? tau / span : 1.0;
    Vec3 p = a.pos + u * d;
    p.z() += 0.5 * physics::kGravity * tau * (span - tau);
    return {p, Phase::Air};
  }
  // A ball said to slide that could not have slid this far still moving was rolling already (a
  // strike at the height of natural roll, an impact that left it rolling): its deceleration then.
  const double g = physics::kGravity;
  const double s = a.after == Phase::Slide
                       ? along(length, span, tau, {params.u_s * g, params.u_r * g}, b.stops)
                       : along(length, span, tau, {params.u_r * g}, b.stops);
  return {length > 0 ? Vec3(a.pos + (s / length) * d) : a.pos, a.after};
}

MotionState stateOf(Phase phase) {
  switch (phase) {
    case Phase::Rest:
      return MotionState::Stationary;
    case Phase::Slide:
      return MotionState::Sliding;
    case Phase::Roll:
      return MotionState::Rolling;
    case Phase::Air:
      return MotionState::Airborne;
    case Phase::Gone:
      return MotionState::Pocketed;
  }
  return MotionState::Stationary;
}

/// A ball of radius `radius` rolled by `step` on the cloth turns about the horizontal axis across
/// its way by |step| / radius.
Quat rolled(const Quat& q, const Vec3& step, double radius) {
  const Vec3 flat(step.x(), step.y(), 0.0);
  const double distance = flat.norm();
  if (distance < 1e-12 || radius <= 0) return q;
  const Vec3 axis = Vec3::UnitZ().cross(flat / distance);
  return (Quat(Eigen::AngleAxisd(distance / radius, axis)) * q).normalized();
}

}  // namespace

std::vector<ReplayFrame> replayFrames(const std::vector<Ball>& before,
                                      const physics::EventLog& events,
                                      const std::vector<Ball>& after, double hz,
                                      const table::PhysicsParams& params) {
  std::map<int, Track> tracks;
  for (const Ball& b : before) {
    Track& track = tracks[b.id];
    track.before = track.after = b;
    track.knots.push_back(Knot{0.0, b.pos, Phase::Rest});
  }
  for (const Ball& b : after) {
    const auto it = tracks.find(b.id);
    if (it != tracks.end()) it->second.after = b;
  }
  double end = 0.0;
  for (const physics::Event& e : events) {
    end = std::max(end, e.t);
    const auto a = tracks.find(e.ball_a);
    if (a != tracks.end() && physics::onTable(a->second.before.state)) {
      auto& knots = a->second.knots;
      const Phase previous = knots.back().after;
      knots.push_back(
          Knot{e.t, e.pos, phaseAfter(e.type, previous), e.type == EventType::RollToRest});
    }
    if (e.type != EventType::BallBall) continue;
    const auto b = tracks.find(e.ball_b);
    if (b == tracks.end() || !physics::onTable(b->second.before.state)) continue;
    Knot knot{e.t, Vec3::Zero(), Phase::Slide, false, true, e.pos};
    b->second.knots.push_back(knot);
  }
  // Knots in time order (stable: the log's order within one instant). A struck ball's own track
  // says where it was; it touched the striker, so it goes where that guess is moved along the
  // line of centres to a ball's width from it.
  for (auto& [id, track] : tracks) {
    auto& knots = track.knots;
    std::stable_sort(knots.begin(), knots.end(),
                     [](const Knot& x, const Knot& y) { return x.t < y.t; });
    const double width = 2.0 * track.before.pos.z();
    for (std::size_t i = 1; i < knots.size(); ++i) {
      Knot& k = knots[i];
      if (!k.estimated) continue;
      const Vec3 guess = trackAt(knots, i);
      const Vec3 apart = guess - k.toucher;
      k.pos =
          apart.norm() > 1e-9 && width > 0 ? Vec3(k.toucher + width * apart.normalized()) : guess;
      k.estimated = false;
    }
  }

  const double dt = 1.0 / std::max(hz, 1.0);
  const int count = static_cast<int>(std::ceil(end / dt - 1e-9));
  std::vector<ReplayFrame> frames;
  frames.reserve(static_cast<std::size_t>(count) + 1);
  std::map<int, Quat> turned;  // each ball's orientation as rolled so far
  std::map<int, Vec3> last;
  for (const Ball& b : before) {
    turned[b.id] = b.orient;
    last[b.id] = b.pos;
  }
  for (int k = 0; k <= count; ++k) {
    const double t = std::min(k * dt, end);
    ReplayFrame frame{t, {}};
    frame.balls.reserve(before.size());
    for (const Ball& b : before) {
      const Track& track = tracks[b.id];
      Ball ball = b;
      if (physics::onTable(b.state)) {
        const auto [at, phase] = place(track, t, params);
        turned[b.id] = rolled(turned[b.id], at - last[b.id], b.pos.z());
        last[b.id] = at;
        ball.pos = phase == Phase::Gone ? track.after.pos : at;
        ball.state = phase == Phase::Gone ? track.after.state : stateOf(phase);
        ball.orient = turned[b.id];  // as rolled; corrected below
        ball.vel = ball.ang_vel = Vec3::Zero();
      }
      frame.balls.push_back(k == count ? track.after : ball);
    }
    frames.push_back(std::move(frame));
  }
  // Rolling alone does not end in `after`'s orientation (sliding turns a ball too): the
  // difference is spread over the shot, so the last frame is `after` itself without a jump.
  for (std::size_t i = 0; i < before.size(); ++i) {
    const Ball& b = before[i];
    if (!physics::onTable(b.state)) continue;
    const Quat correction = tracks[b.id].after.orient * turned[b.id].inverse();
    for (int k = 0; k < count; ++k) {
      ReplayFrame& frame = frames[static_cast<std::size_t>(k)];
      const double u = end > 0 ? frame.t / end : 1.0;
      Quat& q = frame.balls[i].orient;
      q = (Quat::Identity().slerp(u, correction) * q).normalized();
    }
  }
  return frames;
}

}  // namespace pool::app
