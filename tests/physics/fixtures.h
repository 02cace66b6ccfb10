// Shared fixtures of the physics tests: an open cloth without cushions, and helpers to run one
// ball.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "physics/simulation.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::physics::test {

constexpr double kDeg = std::numbers::pi / 180.0;

/// A 100 m × 100 m slate with no cushions and no pockets: closed-form motion, undisturbed.
inline table::TableSpec openSpec() {
  table::TableSpec s;
  s.name = "open";
  s.length = 100.0;
  s.width = 100.0;
  return s;
}

inline table::TableGeometry openGeometry(const table::TableSpec& s) {
  table::TableGeometry g;
  g.length = s.length;
  g.width = s.width;
  return g;
}

inline Ball ballAt(int id, double x, double y, double R = 0.028575) {
  Ball b;
  b.id = id;
  b.pos = Vec3(x, y, R);
  return b;
}

/// Events of one type for one ball.
inline std::vector<Event> eventsOf(const ShotOutcome& o, EventType type, int ball) {
  std::vector<Event> out;
  for (const auto& e : o.events) {
    if (e.type == type && e.ball_a == ball) out.push_back(e);
  }
  return out;
}

inline const Ball& ballById(const ShotOutcome& o, int id) {
  for (const auto& b : o.balls) {
    if (b.id == id) return b;
  }
  return o.balls.front();
}

/// Places the balls and shoots. A refused placement or shot fails the calling test (with the
/// reason) and returns an empty outcome, which the caller's own checks then also reject.
inline ShotOutcome placeAndShoot(Simulation& sim, const std::vector<Ball>& balls,
                                 const CueShot& shot, const SimOptions& options) {
  if (auto placed = sim.setBalls(balls); !placed) {
    ADD_FAILURE() << "placement refused: " << placed.error();
    return {};
  }
  auto out = sim.shoot(shot, options);
  if (!out) {
    ADD_FAILURE() << "shot refused: " << out.error();
    return {};
  }
  return *out;
}

/// Runs one shot on the open cloth; fails the test if placement or shot are refused.
inline ShotOutcome shootOpen(const table::TableSpec& spec, std::vector<Ball> balls,
                             const CueShot& shot, SimOptions options = {}) {
  Simulation sim(spec, openGeometry(spec));
  return placeAndShoot(sim, balls, shot, options);
}

}  // namespace pool::physics::test

namespace pool::physics::test {

/// A ball already moving on the open cloth (state from its velocities), for collision tests.
inline Ball movingBall(int id, double x, double y, const Vec3& vel, const Vec3& ang_vel,
                       double R = 0.028575) {
  Ball b = ballAt(id, x, y, R);
  b.vel = vel;
  b.ang_vel = ang_vel;
  b.state = MotionState::Sliding;
  return b;
}

/// Runs balls already in motion on the open cloth, sampling at `hz`; fails the test if the
/// placement is refused.
inline ShotOutcome runOpen(const table::TableSpec& spec, const std::vector<Ball>& balls,
                           double hz = 0.0) {
  Simulation sim(spec, openGeometry(spec));
  if (auto placed = sim.setBalls(balls); !placed) {
    ADD_FAILURE() << "placement refused: " << placed.error();
    return {};
  }
  SimOptions opt;
  opt.sample_hz = hz;
  return sim.run(opt);
}

/// The first sample strictly after time t, or null when the trajectory ends first (or t is NaN,
/// an event that never happened): a check "just after an event" asserts that it has one.
inline const Sample* sampleAfter(const ShotOutcome& o, double t) {
  for (const auto& s : o.trajectory) {
    if (s.t > t) return &s;
  }
  return nullptr;
}

/// The first sample at or after time t, or null as for sampleAfter.
inline const Sample* sampleFrom(const ShotOutcome& o, double t) {
  for (const auto& s : o.trajectory) {
    if (s.t >= t) return &s;
  }
  return nullptr;
}

/// The direction (degrees, atan2 in the table plane) of a ball's velocity in the first sample
/// at or after time t; NaN (which fails any comparison) when there is none or t is NaN.
inline double headingAfter(const ShotOutcome& o, int id, double t) {
  for (const auto& s : o.trajectory) {
    if (!(s.t >= t)) continue;
    for (const auto& b : s.balls) {
      if (b.id == id) return std::atan2(b.vel.y(), b.vel.x()) / kDeg;
    }
  }
  return std::nan("");
}

}  // namespace pool::physics::test

#include "table/rack.h"

namespace pool::physics::test {

/// The shipped 9-ft table, its geometry read through assimp as the programs read it.
struct RealTable {
  table::TableSpec spec;
  table::TableGeometry geometry;
};

inline const RealTable& realTable() {
  static const RealTable t = [] {
    RealTable r;
    auto spec = table::loadTableSpec("wpa-9ft");
    if (!spec) throw std::runtime_error(spec.error());
    r.spec = *spec;
    auto geometry = table::loadTableGeometry(r.spec);
    if (!geometry) throw std::runtime_error(geometry.error());
    r.geometry = *geometry;
    return r;
  }();
  return t;
}

/// Shoots on the real table; fails the test (with the reason, and an empty outcome) if placement
/// or shot are refused.
inline ShotOutcome shootReal(const std::vector<Ball>& balls, const CueShot& shot,
                             SimOptions options = {}) {
  const auto& t = realTable();
  Simulation sim(t.spec, t.geometry);
  return placeAndShoot(sim, balls, shot, options);
}

/// The 8-ball break of the issue: rack of seed 0, cue ball on the head spot, 8 m/s at the apex.
/// An 8-ball rack of `seed` laid out by `generator`, the cue ball on the head spot.
inline std::vector<Ball> breakBalls(table::RackGenerator generator = table::RackGenerator::Frozen,
                                    std::uint64_t seed = 0) {
  const auto& t = realTable();
  const double R = t.spec.params.ball_radius;
  const auto spots = table::spotsFor(t.spec);
  std::vector<Ball> balls{ballAt(0, spots.head_spot.x(), spots.head_spot.y(), R)};
  for (const auto& p : table::rackFor(table::RackType::EightBall, t.spec, R, seed, generator)) {
    balls.push_back(ballAt(p.id, p.pos.x(), p.pos.y(), R));
  }
  return balls;
}

inline CueShot breakShot() {
  CueShot shot;
  shot.speed = 8.0;
  return shot;
}

}  // namespace pool::physics::test
