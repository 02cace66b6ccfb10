// Balls that dropped into a pocket: a second ODE world with the table's triangle mesh, where they
// fall through the hole into the trough.
#pragma once

#include <memory>
#include <vector>

#include "physics/ball.h"
#include "table/physics_params.h"
#include "table/table_geometry.h"

namespace pool::physics {

/// Once a ball's centre passes over a pocket's hole it belongs here: ODE steps it at a fixed
/// 2 ms under gravity, with contact joints against the collision mesh (the slate's rim, the
/// pocket liner, the trough) and the other dropped balls. Its motion no longer counts for the
/// shot's rest. Time runs on a fixed grid from the shot's start, so sampling never changes it.
class PocketWorld {
 public:
  PocketWorld(const table::TableGeometry& geometry, const table::PhysicsParams& params);
  ~PocketWorld();
  PocketWorld(const PocketWorld&) = delete;
  PocketWorld& operator=(const PocketWorld&) = delete;

  /// Forgets every dropped ball and starts the clock again at 0 (a new shot).
  void clear();
  /// Steps to time t (s from the strike), then adds `ball` (pose and velocities) as it is,
  /// over the hole centred at `hole`.
  void drop(const Ball& ball, const Vec2& hole, double t);
  /// Steps every dropped ball up to the last grid point at or before t.
  void advanceTo(double t);
  /// Steps until every dropped ball rests (or has had its time), then stops.
  void settle();
  /// Writes the pose and velocities of dropped ball `id` into `ball`; false if it is not here.
  bool read(int id, Ball& ball) const;
  /// ODE steps taken (for benchmarks).
  std::uint64_t steps() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pool::physics
