// ODE world of the balls: bodies, forces from the cloth model, stepping with exact correction.
#include "physics/ode_world.h"

#include <ode/ode.h>

#include <cstdarg>
#include <mutex>

namespace pool::physics {

namespace {
// ODE's informational messages would go to stderr, which pool-sim keeps empty; nothing in them
// is needed (errors still abort through ODE's own handler).
void quietMessage(int, const char*, va_list) {}
}  // namespace

void ensureOde() {
  static std::once_flag once;
  std::call_once(once, [] {
    dInitODE2(0);
    dSetMessageHandler(quietMessage);
  });
  thread_local bool thread_ready = false;
  if (!thread_ready) {
    dAllocateODEDataForThread(dAllocateMaskAll);
    thread_ready = true;
  }
}

namespace {

Vec3 toVec(const dReal* v) {
  return Vec3(v[0], v[1], v[2]);
}

}  // namespace

Quat integrateOrientation(const Quat& q, const Vec3& w, double dt) {
  const double angle = w.norm() * dt;
  if (angle == 0.0) return q;
  Quat r(Eigen::AngleAxisd(angle, w.normalized()));
  return (r * q).normalized();
}

OdeWorld::OdeWorld(double ball_mass, double ball_radius) : mass_(ball_mass), radius_(ball_radius) {
  ensureOde();
  world_ = dWorldCreate();
  dWorldSetGravity(world_, 0, 0, 0);  // gravity is part of each ball's acceleration
  dWorldSetAutoDisableFlag(world_, 0);
  dWorldSetLinearDamping(world_, 0);
  dWorldSetAngularDamping(world_, 0);
}

OdeWorld::~OdeWorld() {
  if (world_) dWorldDestroy(world_);  // destroys the bodies too
}

int OdeWorld::addBall(const Ball& ball) {
  dBodyID body = dBodyCreate(world_);
  dMass m;
  dMassSetSphereTotal(&m, mass_, radius_);
  dBodySetMass(body, &m);
  // ODE's own rotation is overwritten after every step (integrateOrientation, exact for a fixed
  // axis), so its cheap infinitesimal mode is enough; velocities and positions do not depend on it
  // (a sphere's inertia is the same in every frame).
  dBodySetFiniteRotationMode(body, 0);
  dBodySetGravityMode(body, 0);
  bodies_.push_back(body);
  moving_.push_back(false);
  const int i = static_cast<int>(bodies_.size()) - 1;
  setBall(i, ball, false);
  return i;
}

void OdeWorld::setBall(int i, const Ball& ball, bool moving) {
  PartScope scope(*profiler_, Part::Ode);
  dBodyID body = bodies_[static_cast<size_t>(i)];
  dBodySetPosition(body, ball.pos.x(), ball.pos.y(), ball.pos.z());
  const dReal q[4] = {ball.orient.w(), ball.orient.x(), ball.orient.y(), ball.orient.z()};
  dBodySetQuaternion(body, q);
  dBodySetLinearVel(body, ball.vel.x(), ball.vel.y(), ball.vel.z());
  dBodySetAngularVel(body, ball.ang_vel.x(), ball.ang_vel.y(), ball.ang_vel.z());
  if (moving) {
    dBodyEnable(body);
  } else {
    dBodyDisable(body);
  }
  moving_[static_cast<size_t>(i)] = moving;
}

void OdeWorld::step(double dt, const std::vector<Vec3>& acc, const std::vector<Vec3>& ang_acc,
                    std::vector<Ball>& balls) {
  if (!(dt > 0.0)) return;
  PartScope integration(*profiler_, Part::Integration);
  const double inertia = 0.4 * mass_ * radius_ * radius_;
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (!moving_[i]) continue;
    const Vec3 f = mass_ * acc[i];
    const Vec3 tq = inertia * ang_acc[i];
    dBodyAddForce(bodies_[i], f.x(), f.y(), f.z());
    dBodyAddTorque(bodies_[i], tq.x(), tq.y(), tq.z());
  }
  {
    PartScope ode(*profiler_, Part::Ode);
    dWorldStep(world_, dt);
  }
  for (size_t i = 0; i < bodies_.size(); ++i) {
    if (!moving_[i]) continue;
    Ball& b = balls[i];
    // ODE's x' = x + v'·dt; the exact constant-acceleration path is that minus a·dt²/2.
    const Vec3 pos = toVec(dBodyGetPosition(bodies_[i])) - 0.5 * dt * dt * acc[i];
    const Vec3 w1 = toVec(dBodyGetAngularVel(bodies_[i]));
    b.orient = integrateOrientation(b.orient, 0.5 * (b.ang_vel + w1), dt);
    b.pos = pos;
    b.vel = toVec(dBodyGetLinearVel(bodies_[i]));
    b.ang_vel = w1;
    dBodySetPosition(bodies_[i], pos.x(), pos.y(), pos.z());
    const dReal q[4] = {b.orient.w(), b.orient.x(), b.orient.y(), b.orient.z()};
    dBodySetQuaternion(bodies_[i], q);
  }
}

}  // namespace pool::physics
