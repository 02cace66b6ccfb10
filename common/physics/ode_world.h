// RAII wrapper of the ODE world that integrates the balls between events.
#pragma once

#include <vector>

#include "physics/ball.h"
#include "physics/profile.h"

struct dxWorld;
struct dxBody;

namespace pool::physics {

/// One ODE world with one body per ball. Between events every ball moves under constant
/// accelerations (the cloth model's), which ODE integrates; its semi-implicit Euler position is
/// then corrected by the exact −a·dt²/2 term so that long steps stay exact, and the orientation
/// is advanced by the mean angular velocity over the step (exact for a fixed spin axis).
class OdeWorld {
 public:
  OdeWorld(double ball_mass, double ball_radius);
  ~OdeWorld();
  OdeWorld(const OdeWorld&) = delete;
  OdeWorld& operator=(const OdeWorld&) = delete;

  /// Adds a body for a ball; returns its index (the order of calls).
  int addBall(const Ball& ball);
  /// Copies pose and velocities into body `i`; `moving` enables or disables it.
  void setBall(int i, const Ball& ball, bool moving);
  /// Advances all moving bodies by dt seconds under accelerations acc[i], ang_acc[i] (indexed
  /// like the bodies; ignored for disabled ones), and writes the results back into `balls`.
  void step(double dt, const std::vector<Vec3>& acc, const std::vector<Vec3>& ang_acc,
            std::vector<Ball>& balls);

  std::size_t bodyCount() const { return bodies_.size(); }

  /// Charges ODE's own work to Part::Ode and ours to Part::Integration (null: no profile).
  void setProfiler(Profiler* profiler) { profiler_ = profiler ? profiler : &idle_; }

 private:
  dxWorld* world_ = nullptr;
  std::vector<dxBody*> bodies_;
  std::vector<bool> moving_;
  double mass_;
  double radius_;
  Profiler idle_;  ///< never started: switches cost one branch
  Profiler* profiler_ = &idle_;
};

/// Initialises ODE once per process and its per-thread data once per thread.
void ensureOde();

/// Rotates q by angular velocity w (rad/s) over dt seconds.
Quat integrateOrientation(const Quat& q, const Vec3& w, double dt);

}  // namespace pool::physics
