// Touching balls struck together: order independence, mirror symmetry, momentum, energy and a
// Newton's cradle, for a line of balls and for the 8-ball and 9-ball racks.
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>

#include "fixtures.h"
#include "physics/ball_ball/compliant_cluster.h"
#include "table/rack.h"

namespace pool::physics::test {
namespace {

constexpr double kR = 0.028575;
constexpr double kMass = 0.170097;
constexpr double kTouch = 1e-6;  // m, as the event loop uses it
constexpr double kE = 0.95;

double kinetic(const std::vector<Vec3>& vel) {
  double e = 0.0;
  for (const Vec3& v : vel) e += 0.5 * kMass * v.squaredNorm();
  return e;
}

Vec3 momentum(const std::vector<Vec3>& vel) {
  return kMass * std::accumulate(vel.begin(), vel.end(), Vec3(Vec3::Zero()));
}

/// A rack on the real table and the cue ball touching its apex, heading at it along +x at 8 m/s.
struct RackImpact {
  std::vector<Vec3> pos, vel;
};

RackImpact rackImpact(table::RackType type, std::uint64_t seed) {
  const auto& spec = realTable().spec;
  RackImpact r;
  const auto rack = table::rackBalls(type, spec, kR, seed);
  const Vec2 apex = rack.front().pos;
  r.pos.emplace_back(apex.x() - 2.0 * kR, apex.y(), kR);
  r.vel.emplace_back(8.0, 0.0, 0.0);
  for (const auto& b : rack) {
    r.pos.emplace_back(b.pos.x(), b.pos.y(), kR);
    r.vel.emplace_back(Vec3::Zero());
  }
  return r;
}

/// Index of the ball at `p` (to 1 nm), or the size if none.
size_t at(const std::vector<Vec3>& pos, const Vec3& p) {
  for (size_t k = 0; k < pos.size(); ++k) {
    if ((pos[k] - p).norm() < 1e-9) return k;
  }
  return pos.size();
}

// A striker into a line of five touching balls on its axis. A plain simultaneous impulse would
// push the line as one block (every ball at v/6); Hertzian contacts pass a pulse along it: the
// last ball leaves with most of the speed (≥ 85 %) and every other one keeps under 15 %. The
// chain is dispersive, so the last two share a little (Hinch & Saint-Jean 1999).
TEST(CompliantCluster, NewtonsCradlePassesTheHitToTheLastBall) {
  std::vector<Vec3> pos, vel;
  for (int k = 0; k < 6; ++k) {
    pos.emplace_back(2.0 * kR * k, 0.0, kR);
    vel.emplace_back(k == 0 ? 2.0 : 0.0, 0.0, 0.0);
  }
  const auto contacts = resolveCompliantCluster(pos, vel, kE, kR, kMass, kTouch);
  EXPECT_EQ(contacts.size(), 5u);  // one per touching pair
  EXPECT_GE(vel[5].x(), 0.85 * 2.0);
  for (int k = 0; k < 5; ++k) EXPECT_LT(vel[k].norm(), 0.15 * 2.0) << k;
  EXPECT_NEAR(momentum(vel).x(), kMass * 2.0, 1e-12);
  EXPECT_LE(kinetic(vel), 0.5 * kMass * 4.0);
}

// Two balls alone: the hysteresis returns e² of the energy, so they part at e times their
// approach speed (closed form); 1e-4: the time steps resolve the contact to 1/50 of its length.
TEST(CompliantCluster, TwoBallsPartAtETimesTheirApproachSpeed) {
  std::vector<Vec3> pos{{0, 0, kR}, {2 * kR, 0, kR}}, vel{{3.0, 0, 0}, {0, 0, 0}};
  resolveCompliantCluster(pos, vel, kE, kR, kMass, kTouch);
  EXPECT_NEAR((vel[1] - vel[0]).x(), kE * 3.0, 1e-4 * 3.0);
  EXPECT_NEAR(momentum(vel).x(), kMass * 3.0, 1e-12);
}

class RackCluster : public ::testing::TestWithParam<table::RackType> {};

// Momentum is conserved pair by pair and the energy never rises.
TEST_P(RackCluster, ConservesMomentumAndNeverAddsEnergy) {
  RackImpact r = rackImpact(GetParam(), 0);
  const Vec3 p0 = momentum(r.vel);
  const double e0 = kinetic(r.vel);
  resolveCompliantCluster(r.pos, r.vel, kE, kR, kMass, kTouch);
  EXPECT_LT((momentum(r.vel) - p0).norm(), 1e-12 * p0.norm());
  EXPECT_LE(kinetic(r.vel), e0);
  EXPECT_GT(kinetic(r.vel), 0.5 * e0);  // the balls do move
}

// The balls given in reverse order come out the same, ball by ball (1e-9 relative).
TEST_P(RackCluster, TheOrderOfTheBallsChangesNothing) {
  RackImpact a = rackImpact(GetParam(), 0);
  RackImpact b = a;
  std::reverse(b.pos.begin(), b.pos.end());
  std::reverse(b.vel.begin(), b.vel.end());
  resolveCompliantCluster(a.pos, a.vel, kE, kR, kMass, kTouch);
  resolveCompliantCluster(b.pos, b.vel, kE, kR, kMass, kTouch);
  for (size_t k = 0; k < a.pos.size(); ++k) {
    const size_t m = at(b.pos, a.pos[k]);
    ASSERT_LT(m, b.pos.size());
    EXPECT_LT((a.vel[k] - b.vel[m]).norm(), 1e-9 * 8.0) << k;
  }
}

// A dead-centre hit on the symmetric rack: every ball's velocity mirrors its mirror image's
// across the rack's axis (1e-6 relative to the cue ball's speed).
TEST_P(RackCluster, ADeadCentreHitGivesMirrorImages) {
  RackImpact r = rackImpact(GetParam(), 0);
  resolveCompliantCluster(r.pos, r.vel, kE, kR, kMass, kTouch);
  const double axis = r.pos.front().y();
  for (size_t k = 0; k < r.pos.size(); ++k) {
    const Vec3 mirror_pos(r.pos[k].x(), 2.0 * axis - r.pos[k].y(), kR);
    size_t m = r.pos.size();
    for (size_t j = 0; j < r.pos.size(); ++j) {
      if ((r.pos[j] - mirror_pos).norm() < 1e-9) m = j;
    }
    ASSERT_LT(m, r.pos.size()) << k;
    const Vec3 mirrored(r.vel[m].x(), -r.vel[m].y(), r.vel[m].z());
    EXPECT_LT((r.vel[k] - mirrored).norm(), 1e-6 * 8.0) << k;
  }
}

/// The rack of `seed` on the real table, the cue ball 0.1 m in front of the apex on its axis,
/// struck dead centre (stun, 8 m/s); every ball 50 ms after the strike, by starting position.
std::vector<std::pair<Vec3, Vec3>> fiftyMsAfter(table::RackType type, std::uint64_t seed) {
  const auto& spec = realTable().spec;
  const auto rack = table::rackBalls(type, spec, kR, seed);
  std::vector<Ball> balls{ballAt(0, rack.front().pos.x() - 0.1, rack.front().pos.y(), kR)};
  for (const auto& b : rack) balls.push_back(ballAt(b.id, b.pos.x(), b.pos.y(), kR));
  CueShot shot;
  shot.speed = 8.0;
  shot.speed_is_ball = true;
  SimOptions opt;
  opt.sample_hz = 20.0;  // samples at 0 and 50 ms
  const auto out = shootReal(balls, shot, opt);
  std::vector<std::pair<Vec3, Vec3>> moved;
  for (const Ball& b : balls) {
    for (const Ball& later : out.trajectory.at(1).balls) {
      if (later.id == b.id) moved.emplace_back(b.pos, later.pos);
    }
  }
  return moved;
}

// On the table: labels shuffled by another seed (same places, other ids) leave every place's
// ball at the same point 50 ms after the strike (1e-9 m), and the dead-centre hit leaves mirror
// images (1 µm).
TEST_P(RackCluster, OnTheTableLabelsDoNotMatterAndTheBreakIsMirrored) {
  const auto a = fiftyMsAfter(GetParam(), 0);
  const auto b = fiftyMsAfter(GetParam(), 7);
  ASSERT_EQ(a.size(), b.size());
  const double axis = a.front().first.y();
  for (const auto& [start, end] : a) {
    bool relabelled = false, mirrored = false;
    for (const auto& [start_b, end_b] : b) {
      if ((start_b - start).norm() < 1e-9) {
        relabelled = true;
        EXPECT_LT((end_b - end).norm(), 1e-9);
      }
    }
    for (const auto& [start_m, end_m] : a) {
      if ((start_m - Vec3(start.x(), 2.0 * axis - start.y(), start.z())).norm() < 1e-9) {
        mirrored = true;
        EXPECT_LT((Vec3(end_m.x(), 2.0 * axis - end_m.y(), end_m.z()) - end).norm(), 1e-6);
      }
    }
    EXPECT_TRUE(relabelled && mirrored);
    EXPECT_GT((end - start).norm(), 0.0);
  }
}

INSTANTIATE_TEST_SUITE_P(Racks, RackCluster,
                         ::testing::Values(table::RackType::EightBall, table::RackType::NineBall));

}  // namespace
}  // namespace pool::physics::test
