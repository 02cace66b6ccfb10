// Ball–cloth model of Leckie & Greenspan (2005): sliding friction, rolling resistance, spin decay.
#include <cmath>
#include <limits>

#include "physics/ball_cloth/cloth_model.h"

namespace pool::physics {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
// Below these a velocity or spin is zero (1 µm/s, 1 µrad/s): they only absorb rounding left
// after the exact transitions.
constexpr double kSpeedEps = 1e-6;
constexpr double kSpinEps = 1e-6;

class ClothLeckieGreenspan final : public ClothModel {
 public:
  explicit ClothLeckieGreenspan(const table::PhysicsParams& p) : p_(p) {}

  ClothMotion motion(const Ball& b) const override {
    switch (b.state) {
      case MotionState::Sliding:
        return sliding(b);
      case MotionState::Rolling:
        return rolling(b);
      case MotionState::Spinning:
        return spinning(b);
      case MotionState::Airborne:
        return airborne(b);
      default:
        return ClothMotion{Vec3::Zero(), Vec3::Zero(), kInf, Transition::None};
    }
  }

  void apply(Transition t, Ball& b) const override {
    switch (t) {
      case Transition::SlideToRoll:
        b.vel.z() = 0.0;
        b.ang_vel.head<2>() = rollingSpin(b.vel);
        b.state = MotionState::Rolling;
        break;
      case Transition::RollToRest:
        b.vel.setZero();
        b.ang_vel.x() = 0.0;
        b.ang_vel.y() = 0.0;
        b.state =
            std::abs(b.ang_vel.z()) > kSpinEps ? MotionState::Spinning : MotionState::Stationary;
        if (b.state == MotionState::Stationary) b.ang_vel.z() = 0.0;
        break;
      case Transition::SpinEnds:
        b.ang_vel.z() = 0.0;
        b.state = classify(b);
        break;
      default:
        break;
    }
  }

  MotionState classify(const Ball& b) const override {
    const Vec2 v = b.vel.head<2>();
    const Vec2 slip = slipVelocity(b);
    if (slip.norm() > kSpeedEps) return MotionState::Sliding;
    if (v.norm() > kSpeedEps) return MotionState::Rolling;
    if (std::abs(b.ang_vel.z()) > kSpinEps) return MotionState::Spinning;
    return MotionState::Stationary;
  }

 private:
  double R() const { return p_.ball_radius; }

  /// Horizontal velocity of the contact point: v + ω × (−R ẑ).
  Vec2 slipVelocity(const Ball& b) const {
    return Vec2(b.vel.x() - R() * b.ang_vel.y(), b.vel.y() + R() * b.ang_vel.x());
  }

  /// Horizontal spin of pure rolling at velocity v: ω = ẑ × v / R.
  Vec2 rollingSpin(const Vec3& v) const { return Vec2(-v.y() / R(), v.x() / R()); }

  /// Spin about the vertical decays at its own rate, independent of the rest.
  void addSpinDecay(const Ball& b, ClothMotion& m) const {
    const double wz = b.ang_vel.z();
    if (std::abs(wz) <= kSpinEps) return;
    m.ang_acc.z() = wz > 0 ? -p_.spin_decel : p_.spin_decel;
    const double t = std::abs(wz) / p_.spin_decel;
    if (t < m.duration) {
      m.duration = t;
      m.ends_with = Transition::SpinEnds;
    }
  }

  ClothMotion sliding(const Ball& b) const {
    ClothMotion m;
    const Vec2 slip = slipVelocity(b);
    const double s = slip.norm();
    if (s > 0.0) {
      // Friction u_s·m·g against the slip; its torque about the centre (contact at −R ẑ) makes
      // the slip fall at 7/2·u_s·g, so sliding ends after 2|u|/(7 u_s g).
      const Vec2 a = -p_.u_s * kGravity / s * slip;
      m.acc = Vec3(a.x(), a.y(), 0.0);
      m.ang_acc = Vec3(2.5 / R() * a.y(), -2.5 / R() * a.x(), 0.0);
      m.duration = 2.0 * s / (7.0 * p_.u_s * kGravity);
      m.ends_with = Transition::SlideToRoll;
    } else {
      m.duration = 0.0;
      m.ends_with = Transition::SlideToRoll;
    }
    addSpinDecay(b, m);
    return m;
  }

  ClothMotion rolling(const Ball& b) const {
    ClothMotion m;
    const Vec2 v = b.vel.head<2>();
    const double speed = v.norm();
    // v and ω·R fall together at u_r·g: the ball stays in pure roll.
    const Vec2 a = speed > 0.0 ? Vec2(-p_.u_r * kGravity / speed * v) : Vec2::Zero();
    m.acc = Vec3(a.x(), a.y(), 0.0);
    m.ang_acc = Vec3(-a.y() / R(), a.x() / R(), 0.0);
    m.duration = speed / (p_.u_r * kGravity);
    m.ends_with = Transition::RollToRest;
    addSpinDecay(b, m);
    return m;
  }

  ClothMotion spinning(const Ball& b) const {
    ClothMotion m;
    m.duration = kInf;
    m.ends_with = Transition::None;
    addSpinDecay(b, m);
    return m;
  }

  ClothMotion airborne(const Ball& b) const {
    ClothMotion m;
    m.acc = Vec3(0.0, 0.0, -kGravity);
    // Lands when z returns to R: z + vz t − g t²/2 = R.
    const double h = b.pos.z() - R();
    const double vz = b.vel.z();
    const double disc = vz * vz + 2.0 * kGravity * std::max(0.0, h);
    m.duration = (vz + std::sqrt(disc)) / kGravity;
    m.ends_with = Transition::Landing;
    return m;
  }

  table::PhysicsParams p_;
};

}  // namespace

std::unique_ptr<ClothModel> makeClothLeckieGreenspan(const table::PhysicsParams& params) {
  return std::make_unique<ClothLeckieGreenspan>(params);
}

}  // namespace pool::physics
