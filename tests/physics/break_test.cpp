// The 8-ball break on the real table: rest, no overlaps, nothing in a cushion, energy never rises,
// determinism.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>

#include "fixtures.h"
#include "physics/watchdog.h"

namespace pool::physics::test {
namespace {

double energy(const std::vector<Ball>& balls, const table::PhysicsParams& p) {
  const double inertia = 0.4 * p.ball_mass * p.ball_radius * p.ball_radius;
  double e = 0.0;
  for (const Ball& b : balls) {
    if (!onTable(b.state)) continue;
    e += 0.5 * p.ball_mass * b.vel.squaredNorm() + 0.5 * inertia * b.ang_vel.squaredNorm() +
         p.ball_mass * kGravity * (b.pos.z() - p.ball_radius);
  }
  return e;
}

/// FNV-1a over every event and the final balls, bit for bit.
std::uint64_t hashOutcome(const ShotOutcome& o) {
  std::uint64_t h = 1469598103934665603ull;
  auto mix = [&h](const void* data, size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (size_t i = 0; i < n; ++i) {
      h ^= bytes[i];
      h *= 1099511628211ull;
    }
  };
  for (const Event& e : o.events) {
    mix(&e.t, sizeof e.t);
    mix(&e.type, sizeof e.type);
    mix(&e.ball_a, sizeof e.ball_a);
    mix(&e.ball_b, sizeof e.ball_b);
    mix(e.where.data(), e.where.size());
    mix(e.pos.data(), sizeof(double) * 3);
  }
  for (const Ball& b : o.balls) mix(b.pos.data(), sizeof(double) * 3);
  return h;
}

class Break : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    SimOptions opt;
    opt.sample_hz = 500.0;
    outcome_ = new ShotOutcome(shootReal(breakBalls(), breakShot(), opt));
  }
  static void TearDownTestSuite() { delete outcome_; }
  static ShotOutcome* outcome_;
};
ShotOutcome* Break::outcome_ = nullptr;

TEST_F(Break, EveryBallComesToRest) {
  const auto& o = *outcome_;
  ASSERT_FALSE(o.truncated);
  ASSERT_TRUE(o.t_rest.has_value());
  EXPECT_GT(*o.t_rest, 1.0);
  EXPECT_EQ(o.balls.size(), 16u);
  for (const Ball& b : o.balls) {
    EXPECT_TRUE(b.state == MotionState::Stationary || b.state == MotionState::Pocketed ||
                b.state == MotionState::OffTable)
        << "ball " << b.id << " " << toString(b.state);
  }
  for (const Event& e : o.events) EXPECT_NE(e.type, EventType::Respot) << e.where;
}

TEST_F(Break, NoOverlapsAndNothingInsideACushion) {
  const auto& t = realTable();
  const auto features = TableFeatures::from(t.geometry);
  const double R = t.spec.params.ball_radius;
  const double lift = t.spec.params.cushion_height - R;
  const double dh = std::sqrt(R * R - lift * lift);
  // Contacts are found to a few ulps of time: 1 µm of overlap is generous.
  constexpr double tol = 1e-6;
  for (const auto& s : outcome_->trajectory) {
    for (size_t i = 0; i < s.balls.size(); ++i) {
      const Ball& a = s.balls[i];
      if (!onTable(a.state)) continue;
      for (size_t k = i + 1; k < s.balls.size(); ++k) {
        if (!onTable(s.balls[k].state)) continue;
        EXPECT_GE((a.pos - s.balls[k].pos).norm(), 2 * R - tol)
            << "t=" << s.t << " balls " << a.id << "," << s.balls[k].id;
      }
      for (const auto& n : features.noses) {
        const Vec2 d = a.pos.head<2>() - n.a;
        const double q = d.dot(n.dir);
        if (q < 0 || q > n.length || a.state == MotionState::Airborne) continue;
        EXPECT_GE(d.dot(n.normal), dh - tol) << "t=" << s.t << " ball " << a.id << " " << n.name;
      }
    }
  }
  for (const Ball& b : outcome_->balls) {
    if (onTable(b.state)) {
      EXPECT_TRUE(onSlate(b.pos.head<2>(), features, t.spec.params)) << b.id;
    }
  }
}

TEST_F(Break, MechanicalEnergyNeverRises) {
  const auto& p = realTable().spec.params;
  double last = std::numeric_limits<double>::infinity();
  for (const auto& s : outcome_->trajectory) {
    const double e = energy(s.balls, p);
    // Rounding of the sums: 1e-9 J against a break of ~5 J.
    EXPECT_LE(e, last + 1e-9) << "t=" << s.t;
    last = e;
  }
}

TEST_F(Break, MiddleBallsBarelyMoveWhileTheBackCornersFly) {
  // 20 ms after the cue ball first touches the apex, the back corners of the rack have left
  // fast while the balls in the middle of the rack have hardly moved.
  double t_hit = std::nan("");
  for (const Event& e : outcome_->events) {
    if (e.type == EventType::BallBall) {
      t_hit = e.t;
      break;
    }
  }
  ASSERT_FALSE(std::isnan(t_hit)) << "the cue ball never touched the rack";
  const Sample* s = sampleFrom(*outcome_, t_hit + 0.02);
  ASSERT_NE(s, nullptr) << "no sample 20 ms after the first contact";
  const auto balls = breakBalls();
  double corner = 0, middle = 0;
  int corners = 0, middles = 0;
  for (const Ball& start : balls) {
    const Ball& now = s->balls[static_cast<size_t>(start.id)];  // samples are sorted by id
    const double moved = (now.pos - start.pos).norm();
    const double x = start.pos.x() - table::spotsFor(realTable().spec).foot_spot.x();
    const double row = x / (2 * 0.028575 * std::sqrt(3.0) / 2.0);
    if (std::lround(row) == 4 && std::abs(std::abs(start.pos.y()) - 4 * 0.028575) < 0.01) {
      corner = std::max(corner, moved);
      ++corners;
    }
    if (std::lround(row) == 2 && std::abs(start.pos.y()) < 0.01) {
      middle = moved;
      ++middles;
    }
  }
  ASSERT_EQ(corners, 2) << "the rack's two back corners were not found";
  ASSERT_EQ(middles, 1) << "the rack's middle ball was not found";
  EXPECT_GT(corner, 0.03) << "back corners barely moved";
  EXPECT_LT(middle, 0.25 * corner) << "the middle ball moved as much as the corners";
}

TEST_F(Break, RerunGivesTheSameEventLog) {
  SimOptions opt;
  opt.sample_hz = 500.0;
  const auto again = shootReal(breakBalls(), breakShot(), opt);
  EXPECT_EQ(hashOutcome(again), hashOutcome(*outcome_));
  // Sampling never changes the simulation itself.
  const auto unsampled = shootReal(breakBalls(), breakShot());
  EXPECT_EQ(hashOutcome(unsampled), hashOutcome(*outcome_));
}

TEST_F(Break, GoldenHash) {
  // Changes whenever the physics changes on purpose: update it then, and say why in the commit.
  constexpr std::uint64_t kGolden = 0x50577648ba889886ull;
  EXPECT_EQ(hashOutcome(*outcome_), kGolden) << "0x" << std::hex << hashOutcome(*outcome_);
}

}  // namespace
}  // namespace pool::physics::test
