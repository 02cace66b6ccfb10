// Cushion rebounds on the real table: the nose above the centre, running and reverse English.
#include <gtest/gtest.h>

#include "fixtures.h"

namespace pool::physics::test {
namespace {

struct Rebound {
  double angle_from_normal;  ///< degrees, outgoing, measured from the rail's normal
  double speed;              ///< m/s, just after the impact
  double normal_in, normal_out;
};

/// A ball heading 60° from +x into the foot_left rail (y = +W/2), 30° from the rail's normal,
/// struck with side `side` (a bank a player would put English on).
Rebound bank(double side) {
  const double R = realTable().spec.params.ball_radius;
  CueShot shot;
  shot.yaw = 60 * kDeg;
  shot.speed = 1.5;
  shot.speed_is_ball = true;  // no squirt: every case arrives on the same line
  shot.tip_side = side;
  shot.tip_height = 0.2;
  SimOptions opt;
  opt.sample_hz = 20000;
  const auto out = shootReal({ballAt(0, 0.2, 0.35, R)}, shot, opt);
  Rebound r{};
  for (const auto& e : out.events) {
    if (e.type != EventType::BallCushion) continue;
    EXPECT_EQ(e.where, "foot_left");
    Vec3 before = Vec3::Zero(), after = Vec3::Zero();
    for (const auto& s : out.trajectory) {
      if (s.t < e.t) before = s.balls[0].vel;
      if (s.t > e.t) {
        after = s.balls[0].vel;
        break;
      }
    }
    r.angle_from_normal = std::atan2(after.x(), -after.y()) / kDeg;
    r.speed = after.head<2>().norm();
    r.normal_in = before.y();
    r.normal_out = -after.y();
    break;
  }
  return r;
}

TEST(Cushion, RunningEnglishWidensAndReverseNarrowsTheRebound) {
  const Rebound none = bank(0.0);
  const Rebound running = bank(0.4);  // right English on a ball going left along the rail
  const Rebound reverse = bank(-0.4);
  ASSERT_GT(none.speed, 0.0);
  EXPECT_GT(running.angle_from_normal, none.angle_from_normal + 2.0);
  EXPECT_LT(reverse.angle_from_normal, none.angle_from_normal - 2.0);
  EXPECT_GT(running.speed, none.speed);
  EXPECT_LT(reverse.speed, none.speed);
}

// The normal speed after the impact is about e_c times the speed in (docs/PHYSICS.md). A nose above
// the centre tilts the impulse down into the slate, which absorbs that part, so the horizontal
// normal speed comes back at e_c·cos²θ-ish: within 0.7·e_c .. e_c.
TEST(Cushion, NormalSpeedComesBackScaledByRestitution) {
  const Rebound r = bank(0.0);
  const double e = realTable().spec.params.e_c;
  EXPECT_LE(r.normal_out, e * r.normal_in + 1e-9);
  EXPECT_GE(r.normal_out, 0.7 * e * r.normal_in);
}

}  // namespace
}  // namespace pool::physics::test
