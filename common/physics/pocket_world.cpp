// The pocket world: ODE bodies, a trimesh of the table and contact joints, stepped at 2 ms.
#include "physics/pocket_world.h"

#include <ode/ode.h>

#include <cmath>
#include <cstring>
#include <map>
#include <mutex>

#include "physics/ode_world.h"

namespace pool::physics {

namespace {

constexpr double kStep = 2e-3;        // s: a falling ball moves a few mm per step
constexpr double kMaxFallTime = 0.3;  // s after the drop; a normal drop takes about 0.15 s
constexpr int kMaxContacts = 4;

struct Dropped {
  int id = 0;
  dBodyID body = nullptr;
  dGeomID geom = nullptr;
  double dropped_at = 0.0;
  Vec2 hole = Vec2::Zero();  ///< centre of the hole it dropped into
  bool frozen = false;
};

/// The table's triangles as ODE trimesh data. Building it (OPCODE's tree) costs milliseconds, so
/// one copy per distinct mesh is kept for the life of the process and shared by every pocket
/// world; it is read-only once built.
class SharedMesh {
 public:
  explicit SharedMesh(const table::TableGeometry& g) {
    for (const auto& part : g.parts) {
      const auto base = static_cast<dTriIndex>(vertices_.size() / 3);
      for (const auto& v : part.vertices) vertices_.insert(vertices_.end(), {v.x(), v.y(), v.z()});
      for (const auto& t : part.triangles) {
        for (auto i : t) indices_.push_back(base + static_cast<dTriIndex>(i));
      }
    }
    if (indices_.empty()) return;
    data_ = dGeomTriMeshDataCreate();
    // Double vertices need BuildDouble (BuildSingle would read them as floats: no contacts).
    dGeomTriMeshDataBuildDouble(data_, vertices_.data(), 3 * sizeof(double),
                                static_cast<int>(vertices_.size() / 3), indices_.data(),
                                static_cast<int>(indices_.size()), 3 * sizeof(dTriIndex));
  }
  ~SharedMesh() {
    if (data_) dGeomTriMeshDataDestroy(data_);
  }
  SharedMesh(const SharedMesh&) = delete;
  SharedMesh& operator=(const SharedMesh&) = delete;
  dTriMeshDataID data() const { return data_; }

  /// The shared mesh of a geometry (by the contents of its triangles).
  static std::shared_ptr<SharedMesh> of(const table::TableGeometry& g) {
    static std::mutex mutex;
    static std::map<std::uint64_t, std::shared_ptr<SharedMesh>> cache;
    const std::uint64_t key = contentHash(g);
    std::lock_guard lock(mutex);
    auto& mesh = cache[key];
    if (!mesh) mesh = std::make_shared<SharedMesh>(g);
    return mesh;
  }

 private:
  /// FNV-1a over 8-byte words (a shot's pocket world looks its mesh up here, so this is on the
  /// path of every shot that pockets a ball in a new Simulation).
  static std::uint64_t contentHash(const table::TableGeometry& g) {
    std::uint64_t h = 1469598103934665603ull;
    auto mix = [&h](const void* p, size_t n) {
      const auto* b = static_cast<const unsigned char*>(p);
      size_t i = 0;
      for (; i + 8 <= n; i += 8) {
        std::uint64_t word;
        std::memcpy(&word, b + i, 8);
        h = (h ^ word) * 1099511628211ull;
      }
      for (; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
    };
    for (const auto& part : g.parts) {
      mix(part.vertices.data(), part.vertices.size() * sizeof(part.vertices[0]));
      mix(part.triangles.data(), part.triangles.size() * sizeof(part.triangles[0]));
    }
    return h;
  }

  std::vector<double> vertices_;  // x, y, z triples
  std::vector<dTriIndex> indices_;
  dTriMeshDataID data_ = nullptr;
};

}  // namespace

struct PocketWorld::Impl {
  table::PhysicsParams p;
  dWorldID world = nullptr;
  dSpaceID space = nullptr;
  dJointGroupID contacts = nullptr;
  std::shared_ptr<SharedMesh> shared;
  dGeomID mesh = nullptr;
  std::vector<Dropped> balls;
  double now = 0.0;
  std::uint64_t steps = 0;

  Impl(const table::TableGeometry& g, const table::PhysicsParams& params) : p(params) {
    ensureOde();
    world = dWorldCreate();
    dWorldSetGravity(world, 0, 0, -kGravity);
    dWorldSetAutoDisableFlag(world, 0);
    space = dSimpleSpaceCreate(nullptr);
    contacts = dJointGroupCreate(0);
    shared = SharedMesh::of(g);
    if (shared->data()) mesh = dCreateTriMesh(space, shared->data(), nullptr, nullptr, nullptr);
  }

  ~Impl() {
    dJointGroupDestroy(contacts);
    dSpaceDestroy(space);  // destroys the geoms in it
    dWorldDestroy(world);
  }

  void addContacts(dGeomID a, dGeomID b) {
    dContact c[kMaxContacts];
    const int n = dCollide(a, b, kMaxContacts, &c[0].geom, sizeof(dContact));
    for (int i = 0; i < n; ++i) {
      c[i].surface.mode = dContactBounce | dContactApprox1;
      c[i].surface.mu = p.u_s;
      c[i].surface.bounce = p.e_slate;
      c[i].surface.bounce_vel = 0.05;
      dJointID j = dJointCreateContact(world, contacts, &c[i]);
      dJointAttach(j, dGeomGetBody(c[i].geom.g1), dGeomGetBody(c[i].geom.g2));
    }
  }

  bool anyMoving() const {
    for (const auto& d : balls) {
      if (!d.frozen) return true;
    }
    return false;
  }

  void stepOnce(double dt) {
    for (size_t i = 0; i < balls.size(); ++i) {
      if (balls[i].frozen) continue;
      if (mesh) addContacts(balls[i].geom, mesh);
      for (size_t k = 0; k < balls.size(); ++k) {
        if (k != i && (k > i || balls[k].frozen)) addContacts(balls[i].geom, balls[k].geom);
      }
    }
    dWorldStep(world, dt);
    dJointGroupEmpty(contacts);
    now += dt;
    ++steps;
    freezeDropped();
  }

  /// A ball fully below the slate (one diameter under its surface) is inside the pocket's
  /// liner and cannot come back: it is laid on the trough floor straight below (found by a ray
  /// cast into the mesh) and no longer stepped. One that hangs on the rim for too long is left.
  void freezeDropped() {
    for (auto& d : balls) {
      if (d.frozen) continue;
      const dReal* pos = dBodyGetPosition(d.body);
      const bool through = pos[2] < -2.0 * p.ball_radius;
      if (!through && now - d.dropped_at < kMaxFallTime) continue;
      d.frozen = true;
      // A ball that hung on the rim, or bounced out of a liner, is a pocketed ball all the
      // same: it goes down the middle of its hole.
      if (!through) dBodySetPosition(d.body, d.hole.x(), d.hole.y(), -2.0 * p.ball_radius);
      layOnTroughFloor(d);
      dBodySetLinearVel(d.body, 0, 0, 0);
      dBodySetAngularVel(d.body, 0, 0, 0);
      // Kinematic, not disabled: later balls still land on it as on a fixed one.
      dBodySetKinematic(d.body);
    }
  }

  void layOnTroughFloor(const Dropped& d) {
    const dReal* pos = dBodyGetPosition(d.body);
    dGeomID ray = dCreateRay(nullptr, 1.0);
    dGeomRaySet(ray, pos[0], pos[1], pos[2], 0, 0, -1);
    dGeomRaySetClosestHit(ray, 1);
    dContactGeom hit;
    const int n = mesh ? dCollide(ray, mesh, 1, &hit, sizeof(dContactGeom)) : 0;
    dGeomDestroy(ray);
    if (n == 0) return;
    // Balls already lying there: stack along x so two never share a place.
    double x = pos[0];
    for (const auto& other : balls) {
      if (!other.frozen || other.body == d.body) continue;
      const dReal* o = dBodyGetPosition(other.body);
      if (std::abs(o[0] - x) < 2.0 * p.ball_radius &&
          std::abs(o[1] - pos[1]) < 2.0 * p.ball_radius) {
        x = o[0] - 2.0 * p.ball_radius * (pos[0] > 0 ? 1.0 : -1.0);
      }
    }
    dBodySetPosition(d.body, x, pos[1], hit.pos[2] + p.ball_radius);
  }

  /// Steps on the grid k·kStep up to t; a drop between grid points adds one partial step.
  void stepTo(double t) {
    while (anyMoving()) {
      const double next_grid = (std::floor(now / kStep + 1e-9) + 1.0) * kStep;
      const double target = std::min(next_grid, t);
      if (target <= now + 1e-12) break;
      stepOnce(target - now);
    }
    if (!anyMoving() && t > now) now = t;
  }
};

PocketWorld::PocketWorld(const table::TableGeometry& geometry, const table::PhysicsParams& params)
    : impl_(std::make_unique<Impl>(geometry, params)) {}

PocketWorld::~PocketWorld() = default;

void PocketWorld::clear() {
  Impl& s = *impl_;
  for (auto& d : s.balls) {
    dGeomDestroy(d.geom);
    dBodyDestroy(d.body);
  }
  s.balls.clear();
  s.now = 0.0;
  s.steps = 0;
}

void PocketWorld::drop(const Ball& ball, const Vec2& hole, double t) {
  Impl& s = *impl_;
  s.stepTo(t);
  s.now = t;
  Dropped d;
  d.id = ball.id;
  d.dropped_at = t;
  d.hole = hole;
  d.body = dBodyCreate(s.world);
  dMass m;
  dMassSetSphereTotal(&m, s.p.ball_mass, s.p.ball_radius);
  dBodySetMass(d.body, &m);
  dBodySetPosition(d.body, ball.pos.x(), ball.pos.y(), ball.pos.z());
  const dReal q[4] = {ball.orient.w(), ball.orient.x(), ball.orient.y(), ball.orient.z()};
  dBodySetQuaternion(d.body, q);
  dBodySetLinearVel(d.body, ball.vel.x(), ball.vel.y(), ball.vel.z());
  dBodySetAngularVel(d.body, ball.ang_vel.x(), ball.ang_vel.y(), ball.ang_vel.z());
  d.geom = dCreateSphere(s.space, s.p.ball_radius);
  dGeomSetBody(d.geom, d.body);
  s.balls.push_back(d);
}

void PocketWorld::advanceTo(double t) {
  const double grid = std::floor(t / kStep + 1e-9) * kStep;
  if (grid > impl_->now) impl_->stepTo(grid);
}

void PocketWorld::settle() {
  while (impl_->anyMoving()) impl_->stepTo(impl_->now + kMaxFallTime);
}

bool PocketWorld::read(int id, Ball& ball) const {
  for (const auto& d : impl_->balls) {
    if (d.id != id) continue;
    const dReal* pos = dBodyGetPosition(d.body);
    const dReal* q = dBodyGetQuaternion(d.body);
    const dReal* v = dBodyGetLinearVel(d.body);
    const dReal* w = dBodyGetAngularVel(d.body);
    ball.pos = Vec3(pos[0], pos[1], pos[2]);
    ball.orient = Quat(q[0], q[1], q[2], q[3]);
    ball.vel = Vec3(v[0], v[1], v[2]);
    ball.ang_vel = Vec3(w[0], w[1], w[2]);
    return true;
  }
  return false;
}

std::uint64_t PocketWorld::steps() const {
  return impl_->steps;
}

}  // namespace pool::physics
