// The event loop: predict the next event, let ODE step every ball exactly to it, resolve it,
// repeat.
#include "physics/simulation.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "physics/ball_ball/compliant_cluster.h"
#include "physics/contact_models.h"
#include "physics/ode_world.h"
#include "physics/pocket_world.h"
#include "physics/predict.h"
#include "physics/watchdog.h"

namespace pool::physics {

namespace {

// An impulse that leaves a ball on the slate rising slower than this is absorbed by the slate
// (a hop under 1 mm); faster, the ball becomes airborne.
constexpr double kLiftOffSpeed = 0.15;  // m/s
// A landing slower than this ends the bouncing: the ball stays on the slate.
constexpr double kSettleSpeed = 0.05;  // m/s
// A shot with more loop turns than this is cut short (a guard, never reached by real shots).
constexpr std::uint64_t kMaxIterations = 200000;
// Contacts slower than this are pushes, not impacts (a ball driven into another, or into a
// cushion, by its own cloth acceleration): no bounce, and the two are set this far apart so the
// next contact is a fresh one. Without it, restitution makes the contacts come ever sooner
// (Zeno) until rounding lets one ball through the other.
constexpr double kPushSpeed = 0.01;  // m/s
constexpr double kPushGap = 1e-7;    // m
// Balls this close (or closer) when one of them is struck take part in the same impact (a rack).
constexpr double kTouchGap = 1e-6;  // m
// Balls this close (or closer) count as overlapping for a placement.
constexpr double kPlacementTolerance = 1e-6;  // m
// An airborne ball this close to the slate is on it for a cushion's or a ball's impulse.
constexpr double kNearSlate = 1e-3;  // m

bool translates(MotionState s) {
  return s == MotionState::Sliding || s == MotionState::Rolling || s == MotionState::Airborne;
}

bool active(MotionState s) {
  return translates(s) || s == MotionState::Spinning;
}

}  // namespace

/// Per ball: its current piece of motion and the next table contact it is heading for.
struct Track {
  ClothMotion motion;
  double t_end = kNever;  ///< absolute time of the motion's transition
  TableHit hit;           ///< absolute time
};

struct Simulation::Impl {
  table::TableSpec spec;
  table::TableGeometry geometry;
  table::PhysicsParams p;
  TableFeatures features;
  ContactModelSet models;
  std::string models_error;  ///< why the spec's models could not be made ("" when they were)
  std::unique_ptr<OdeWorld> world;
  std::unique_ptr<PocketWorld> pockets;  ///< made at the first drop, kept for later shots
  bool dropped = false;                  ///< a ball dropped in this shot
  std::vector<Ball> balls;
  std::vector<Track> tracks;
  std::vector<double> pair_t;  ///< absolute contact time of pair (i, j), i < j, at i * n + j
  std::vector<Vec3> acc, ang_acc;
  double now = 0.0;
  ShotOutcome out;
  SimOptions options;
  std::uint64_t next_sample = 0;
  Profiler profiler;  ///< started by options.profile

  Impl(const table::TableSpec& s, const table::TableGeometry& g)
      : spec(s), geometry(g), p(s.params), features(TableFeatures::from(g)) {
    auto made = makeContactModels(s.models, s.params);
    if (made) {
      models = std::move(*made);
    } else {
      models_error = made.error();
    }
  }

  size_t n() const { return balls.size(); }
  double R() const { return p.ball_radius; }

  Kinematics kinematics(size_t i) const {
    return {balls[i].pos, balls[i].vel, tracks[i].motion.acc};
  }

  void emit(EventType type, size_t i, int other = -1, std::string where = {}, double speed = 0) {
    Event e;
    e.t = now;
    e.type = type;
    e.ball_a = balls[i].id;
    e.ball_b = other;
    e.where = std::move(where);
    e.speed = speed;
    e.pos = balls[i].pos;
    out.events.push_back(std::move(e));
  }

  // --- predictions ---------------------------------------------------------------------

  void predictPair(size_t i, size_t j) {
    double& slot = pair_t[i * n() + j];
    slot = kNever;
    const Ball& a = balls[i];
    const Ball& b = balls[j];
    if (!onTable(a.state) || !onTable(b.state)) return;
    if (!translates(a.state) && !translates(b.state)) return;
    // Up to the first change of either ball's motion: its own transition or table contact (both
    // re-predict every pair of that ball), which keeps the reach test tight.
    const double horizon = std::min({tracks[i].t_end, tracks[j].t_end, tracks[i].hit.t,
                                     tracks[j].hit.t, options.max_time}) -
                           now;
    const double t = pairContactTime(kinematics(i), kinematics(j), R(), horizon);
    if (t < kNever) slot = now + t;
  }

  void predictTable(size_t i) {
    Track& tr = tracks[i];
    tr.hit = TableHit{};
    if (!translates(balls[i].state)) return;
    const bool airborne = balls[i].state == MotionState::Airborne;
    TableHit h = nextTableHit(kinematics(i), airborne, features, R(), p.cushion_height,
                              std::min(tr.t_end, options.max_time) - now);
    if (h.t < kNever) h.t += now;
    tr.hit = h;
  }

  /// The ball's motion changed now: new piece of motion, new predictions, ODE body updated.
  void refresh(size_t i) {
    Track& tr = tracks[i];
    Ball& b = balls[i];
    if (onTable(b.state)) {
      tr.motion = models.cloth->motion(b);
      tr.t_end = now + tr.motion.duration;
    } else {
      tr.motion = ClothMotion{};
      tr.t_end = kNever;
      tr.motion.duration = kNever;
    }
    acc[i] = tr.motion.acc;
    ang_acc[i] = tr.motion.ang_acc;
    world->setBall(static_cast<int>(i), b, active(b.state));
    PartScope prediction(profiler, Part::Prediction);
    predictTable(i);
    for (size_t j = 0; j < n(); ++j) {
      if (j < i) predictPair(j, i);
      if (j > i) predictPair(i, j);
    }
  }

  // --- time ------------------------------------------------------------------------------

  Ball sampleBall(size_t i, double tau) const {
    Ball b = balls[i];
    if (b.state == MotionState::Pocketed && dropped && pockets) {
      pockets->read(b.id, b);
      return b;
    }
    if (!active(b.state) || tau == 0.0) return b;
    const ClothMotion& m = tracks[i].motion;
    b.pos = kinematics(i).at(tau);
    b.vel += tau * m.acc;
    const Vec3 w1 = b.ang_vel + tau * m.ang_acc;
    b.orient = integrateOrientation(b.orient, 0.5 * (b.ang_vel + w1), tau);
    b.ang_vel = w1;
    return b;
  }

  void recordSamples(double until) {
    if (options.sample_hz <= 0.0) return;
    PartScope integration(profiler, Part::Integration);
    while (true) {
      const double ts = static_cast<double>(next_sample) / options.sample_hz;
      if (ts > until) break;
      if (pockets) {
        PartScope pocket_time(profiler, Part::Pockets);
        pockets->advanceTo(ts);
      }
      Sample s;
      s.t = ts;
      s.balls.reserve(n());
      for (size_t i = 0; i < n(); ++i) s.balls.push_back(sampleBall(i, ts - now));
      out.trajectory.push_back(std::move(s));
      ++next_sample;
    }
  }

  void advanceTo(double t) {
    recordSamples(t);
    if (t > now) {
      world->step(t - now, acc, ang_acc, balls);
      ++out.stats.steps;
      now = t;
      if (pockets) {
        PartScope pocket_time(profiler, Part::Pockets);
        pockets->advanceTo(t);
      }
    }
  }

  // --- events ----------------------------------------------------------------------------

  /// After an impulse: a ball on the slate either stays on it (the slate absorbs a downward or
  /// tiny upward speed) or lifts off; its motion state follows from its velocities.
  void settle(size_t i) {
    Ball& b = balls[i];
    const bool was_airborne = b.state == MotionState::Airborne;
    if (was_airborne && b.pos.z() - R() > kNearSlate) return;
    if (b.vel.z() > kLiftOffSpeed) {
      b.state = MotionState::Airborne;
      if (!was_airborne) emit(EventType::Airborne, i);
      return;
    }
    if (was_airborne) emit(EventType::Land, i, -1, {}, std::max(0.0, -b.vel.z()));
    b.vel.z() = 0.0;
    b.pos.z() = R();
    b.state = models.cloth->classify(b);
  }

  /// The ball's centre passed over a hole's edge: it drops, and falls on in the pocket world.
  void pocket(size_t i, const TableFeatures::Hole& hole) {
    Ball& b = balls[i];
    emit(EventType::Pocket, i, -1, hole.name);
    if (!pockets) {
      PartScope setup(profiler, Part::PocketSetup);
      pockets = std::make_unique<PocketWorld>(geometry, p);
    }
    PartScope pocket_time(profiler, Part::Pockets);
    dropped = true;
    pockets->drop(b, hole.c, now);
    b.state = MotionState::Pocketed;
    b.pocket = hole.name;
  }

  void offTable(size_t i, const std::string& over) {
    Ball& b = balls[i];
    emit(EventType::OffTable, i, -1, over);
    b.state = MotionState::OffTable;
    b.vel.setZero();
    b.ang_vel.setZero();
  }

  void transition(size_t i) {
    Ball& b = balls[i];
    const Transition t = tracks[i].motion.ends_with;
    const MotionState before = b.state;
    if (t == Transition::Landing) {
      land(i);
      return;
    }
    models.cloth->apply(t, b);
    if (t == Transition::SlideToRoll) emit(EventType::SlideToRoll, i);
    if (t == Transition::RollToRest) emit(EventType::RollToRest, i);
    if (t == Transition::SpinEnds && before == MotionState::Spinning)
      emit(EventType::SpinToRest, i);
    refresh(i);
  }

  void land(size_t i) {
    Ball& b = balls[i];
    b.pos.z() = R();
    for (const auto& h : features.holes) {
      if ((b.pos.head<2>() - h.c).norm() < h.radius) {
        pocket(i, h);
        refresh(i);
        return;
      }
    }
    emit(EventType::Land, i, -1, {}, -b.vel.z());
    models.slate->bounce(b.vel, b.ang_vel, p.u_s);
    if (b.vel.z() > kSettleSpeed) {
      emit(EventType::Airborne, i);  // bounces: still airborne
    } else {
      b.vel.z() = 0.0;
      b.state = models.cloth->classify(b);
    }
    refresh(i);
  }

  void tableContact(size_t i) {
    Ball& b = balls[i];
    const TableHit hit = tracks[i].hit;
    if (hit.kind == FeatureKind::Hole) {
      const auto& h = features.holes[static_cast<size_t>(hit.index)];
      pocket(i, h);
      refresh(i);
      return;
    }
    if (hit.kind == FeatureKind::OverNose) {
      offTable(i, features.noses[static_cast<size_t>(hit.index)].name);
      refresh(i);
      return;
    }
    const Vec3 normal = contactNormal(b.pos, features, hit.kind, hit.index, p.cushion_height);
    const double approach = -(b.vel + b.ang_vel.cross(-R() * normal)).dot(normal);
    const double e = approach < kPushSpeed ? 0.0 : p.e_c;
    const bool on_slate = b.pos.z() - R() <= kNearSlate;
    const double speed = models.cushion->resolve(b.vel, b.ang_vel, normal, e, on_slate);
    if (approach < kPushSpeed) {
      // A push or a graze: step off the nose so the next contact is predicted afresh.
      const Vec2 away = Vec2(normal.x(), normal.y()).normalized();
      b.pos.head<2>() += kPushGap * away;
    }
    if (speed > 0.0) {
      const std::string& name = hit.kind == FeatureKind::Nose
                                    ? features.noses[static_cast<size_t>(hit.index)].name
                                    : features.points[static_cast<size_t>(hit.index)].name;
      emit(EventType::BallCushion, i, -1, name, speed);
    }
    settle(i);
    refresh(i);
  }

  /// The balls touching i or j, directly or through others (i and j first), on the slate.
  std::vector<size_t> touchingCluster(size_t i, size_t j) const {
    std::vector<size_t> cluster{i, j};
    for (size_t k = 0; k < cluster.size(); ++k) {
      const Ball& c = balls[cluster[k]];
      for (size_t m = 0; m < n(); ++m) {
        const Ball& o = balls[m];
        if (!onTable(o.state) || o.state == MotionState::Airborne) continue;
        if (std::find(cluster.begin(), cluster.end(), m) != cluster.end()) continue;
        if ((o.pos - c.pos).norm() - 2.0 * R() <= kTouchGap) cluster.push_back(m);
      }
    }
    return cluster;
  }

  /// Three or more touching balls: every contact at once, through compliant springs.
  void clusterImpact(const std::vector<size_t>& cluster) {
    std::vector<Vec3> pos, vel;
    for (size_t k : cluster) {
      pos.push_back(balls[k].pos);
      vel.push_back(balls[k].vel);
    }
    const auto contacts = resolveCompliantCluster(pos, vel, p.e_b, R(), p.ball_mass, kTouchGap);
    for (size_t k = 0; k < cluster.size(); ++k) balls[cluster[k]].vel = vel[k];
    for (const ClusterContact& c : contacts) {
      size_t a = cluster[c.a], b = cluster[c.b];
      if (balls[b].id < balls[a].id) std::swap(a, b);
      emit(EventType::BallBall, a, balls[b].id, {}, c.speed);
    }
    for (size_t k : cluster) settle(k);
    for (size_t k : cluster) refresh(k);
  }

  void ballBall(size_t i, size_t j) {
    Ball& a = balls[i];
    Ball& b = balls[j];
    const Vec3 n = (b.pos - a.pos).normalized();
    const double approach =
        (a.vel + a.ang_vel.cross(R() * n) - b.vel - b.ang_vel.cross(-R() * n)).dot(n);
    if (approach >= kPushSpeed && a.state != MotionState::Airborne &&
        b.state != MotionState::Airborne) {
      const std::vector<size_t> cluster = touchingCluster(i, j);
      if (cluster.size() > 2) {
        clusterImpact(cluster);
        return;
      }
    }
    const double e = approach < kPushSpeed ? 0.0 : p.e_b;
    const double speed =
        models.ball_ball->resolve(a.pos, a.vel, a.ang_vel, b.pos, b.vel, b.ang_vel, e);
    if (approach < kPushSpeed) {
      // A push or a graze: part them so the next contact is predicted afresh.
      a.pos -= 0.5 * kPushGap * n;
      b.pos += 0.5 * kPushGap * n;
    }
    if (speed > 0.0) emit(EventType::BallBall, i, b.id, {}, speed);
    settle(i);
    settle(j);
    refresh(i);
    refresh(j);
  }

  // --- the loop --------------------------------------------------------------------------

  enum class Next { None, Transition, Table, Pair };

  Next findNext(double& t, size_t& i, size_t& j) const {
    Next kind = Next::None;
    t = kNever;
    for (size_t k = 0; k < n(); ++k) {
      if (tracks[k].t_end < t) {
        t = tracks[k].t_end;
        kind = Next::Transition;
        i = k;
      }
    }
    for (size_t k = 0; k < n(); ++k) {
      if (tracks[k].hit.t < t) {
        t = tracks[k].hit.t;
        kind = Next::Table;
        i = k;
      }
    }
    for (size_t a = 0; a < n(); ++a) {
      for (size_t b = a + 1; b < n(); ++b) {
        if (pair_t[a * n() + b] < t) {
          t = pair_t[a * n() + b];
          kind = Next::Pair;
          i = a;
          j = b;
        }
      }
    }
    return kind;
  }

  void runLoop() {
    std::uint64_t iterations = 0;
    while (true) {
      double t;
      size_t i = 0, j = 0;
      Next next;
      {
        PartScope prediction(profiler, Part::Prediction);
        next = findNext(t, i, j);
      }
      if (next == Next::None) break;
      if (t > options.max_time) {
        advanceTo(options.max_time);
        out.truncated = true;
        break;
      }
      if (++iterations > kMaxIterations) {
        out.truncated = true;  // stop where we are: stepping on would run past transitions
        break;
      }
      advanceTo(std::max(t, now));
      ++out.stats.events;
      PartScope resolution(profiler, Part::Resolution);
      switch (next) {
        case Next::Transition:
          transition(i);
          break;
        case Next::Table:
          tableContact(i);
          break;
        case Next::Pair:
          ballBall(i, j);
          break;
        case Next::None:
          break;
      }
      std::vector<WatchdogFix> fixes;
      {
        PartScope watchdog(profiler, Part::Watchdog);
        fixes = checkBalls(balls, features, p);
      }
      for (const auto& fix : fixes) applyFix(fix);
    }
  }

  void applyFix(const WatchdogFix& fix) {
    const size_t i = fix.index;
    Ball& b = balls[i];
    emit(EventType::Respot, i, -1, fix.reason);
    if (fix.remove) {
      b.state = MotionState::OffTable;
      b.vel.setZero();
      b.ang_vel.setZero();
    } else {
      b.pos = Vec3(fix.spot.x(), fix.spot.y(), R());
      b.vel.setZero();
      b.ang_vel.setZero();
      b.state = MotionState::Stationary;
    }
    refresh(i);
  }

  /// The layout a shot leaves is the next shot's input: a ball at rest where setBalls would
  /// refuse it (inside a cushion, over a hole, in another ball) is re-spotted here, with an event.
  void checkRestingLayout() {
    const double min_dist = 2.0 * R() - kPlacementTolerance;
    for (size_t i = 0; i < n(); ++i) {
      Ball& b = balls[i];
      if (!onTable(b.state) || b.state == MotionState::Airborne) continue;
      const char* reason =
          onSlate(b.pos.head<2>(), features, p) ? nullptr : "came to rest off the slate";
      for (size_t k = 0; k < i && !reason; ++k) {
        if (onTable(balls[k].state) && (balls[k].pos - b.pos).norm() < min_dist) {
          reason = "came to rest inside another ball";
        }
      }
      if (!reason) continue;
      WatchdogFix fix;
      fix.index = i;
      fix.reason = reason;
      fix.remove = !freeSpotOnLongString(balls, i, features, p, fix.spot);
      applyFix(fix);
    }
  }

  ShotOutcome finish() {
    if (!out.truncated) {
      checkRestingLayout();
      out.t_rest = now;
    }
    recordSamples(now);
    if (pockets) {
      PartScope pocket_time(profiler, Part::Pockets);
      pockets->settle();
      for (Ball& b : balls) {
        if (b.state == MotionState::Pocketed) pockets->read(b.id, b);
      }
      out.stats.pocket_steps = pockets->steps();
    }
    out.balls = balls;
    out.stats.seconds = profiler.stop();
    return std::move(out);
  }

  void reset(const SimOptions& o) {
    out = ShotOutcome{};
    if (pockets) pockets->clear();
    dropped = false;
    options = o;
    now = 0.0;
    next_sample = 0;
    if (o.profile) profiler.start();
  }

  void startTracks() {
    for (size_t i = 0; i < n(); ++i) {
      tracks[i] = Track{};
      tracks[i].t_end = kNever;
    }
    for (size_t i = 0; i < n(); ++i) refresh(i);
  }
};

Check<> checkPlacement(const std::vector<Ball>& balls, const table::TableGeometry& geometry,
                       const table::PhysicsParams& params) {
  std::vector<bool> seen(kMaxBallId + 1, false);
  for (const Ball& b : balls) {
    if (b.id < 0 || b.id > kMaxBallId) {
      return Check<>::refuse("bad_ball_id",
                             "ball id " + std::to_string(b.id) + " is out of range 0..15");
    }
    if (seen[static_cast<size_t>(b.id)])
      return Check<>::refuse("ball_twice", "ball " + std::to_string(b.id) + " is given twice");
    seen[static_cast<size_t>(b.id)] = true;
    if (!b.pos.allFinite() || !b.vel.allFinite() || !b.ang_vel.allFinite()) {
      return Check<>::refuse(
          "non_finite", "ball " + std::to_string(b.id) + " has a non-finite position or velocity");
    }
  }
  const TableFeatures features = TableFeatures::from(geometry);
  for (const Ball& b : balls) {
    if (!onTable(b.state)) continue;
    if (!onSlate(b.pos.head<2>(), features, params)) {
      return Check<>::refuse("off_slate", "ball " + std::to_string(b.id) + " is off the slate");
    }
  }
  // Contacts are resolved to well under a micrometre; touching balls may sit that close.
  const double min_dist = 2.0 * params.ball_radius - kPlacementTolerance;
  for (size_t i = 0; i < balls.size(); ++i) {
    for (size_t k = i + 1; k < balls.size(); ++k) {
      if (!onTable(balls[i].state) || !onTable(balls[k].state)) continue;
      if ((balls[i].pos - balls[k].pos).norm() < min_dist) {
        return Check<>::refuse("overlap", "ball " + std::to_string(balls[i].id) +
                                              " overlaps ball " + std::to_string(balls[k].id));
      }
    }
  }
  return Check<>::pass();
}

Simulation::Simulation(const table::TableSpec& spec, const table::TableGeometry& geometry)
    : impl_(std::make_unique<Impl>(spec, geometry)) {}

Simulation::~Simulation() = default;

Result<bool> Simulation::setBalls(const std::vector<Ball>& balls) {
  if (!impl_->models_error.empty()) return Result<bool>::fail(impl_->models_error);
  if (auto ok = table::validate(impl_->p); !ok) return Result<bool>::fail("params: " + ok.error());
  if (auto ok = checkPlacement(balls, impl_->geometry, impl_->p); !ok) {
    return Result<bool>::fail(ok.error());
  }
  Impl& s = *impl_;
  s.balls = balls;
  std::sort(s.balls.begin(), s.balls.end(),
            [](const Ball& a, const Ball& b) { return a.id < b.id; });
  s.world = std::make_unique<OdeWorld>(s.p.ball_mass, s.R());
  s.world->setProfiler(&s.profiler);
  for (Ball& b : s.balls) {
    if (onTable(b.state) && b.state != MotionState::Airborne) {
      b.pos.z() = s.R();
      b.vel.z() = 0.0;
      b.state = s.models.cloth->classify(b);
    }
    s.world->addBall(b);
  }
  s.tracks.assign(s.n(), Track{});
  s.pair_t.assign(s.n() * s.n(), kNever);
  s.acc.assign(s.n(), Vec3::Zero());
  s.ang_acc.assign(s.n(), Vec3::Zero());
  s.now = 0.0;
  return Result<bool>::ok(true);
}

Result<ShotOutcome> Simulation::shoot(const CueShot& shot, const SimOptions& options) {
  Impl& s = *impl_;
  auto cue = std::find_if(s.balls.begin(), s.balls.end(),
                          [&shot](const Ball& b) { return b.id == shot.ball; });
  if (cue == s.balls.end() || !onTable(cue->state)) {
    return Result<ShotOutcome>::fail(
        shot.ball == kCueBall ? "no cue ball on the table"
                              : "no ball " + std::to_string(shot.ball) + " on the table to strike");
  }
  const auto strike = strikeCueBall(shot, s.p);
  if (!strike) return Result<ShotOutcome>::fail(strike.error());

  s.reset(options);
  const size_t i = static_cast<size_t>(cue - s.balls.begin());
  cue->vel = strike->vel;
  cue->ang_vel = strike->ang_vel;
  s.emit(EventType::Strike, i, -1, {}, strike->vel.norm());
  // An elevated cue drives the ball into the slate, which bounces it (a jump when hard enough).
  // That impact happens while the tip is still on the ball, which pins it: the cloth takes the
  // normal impulse but no friction, so a massé leaves along the cue's line and curves after.
  if (cue->vel.z() < 0.0) {
    s.models.slate->bounce(cue->vel, cue->ang_vel, 0.0);
  }
  cue->state = MotionState::Sliding;
  s.settle(i);
  s.startTracks();
  s.runLoop();
  return Result<ShotOutcome>::ok(s.finish());
}

ShotOutcome Simulation::run(const SimOptions& options) {
  Impl& s = *impl_;
  s.reset(options);
  s.startTracks();
  s.runLoop();
  return s.finish();
}

const std::vector<Ball>& Simulation::balls() const {
  return impl_->balls;
}

}  // namespace pool::physics
