// The cue stroking through after a shot, this screen's or a remote shooter's.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <utility>

#include "client/app/aim.h"
#include "client/app/aim_follower.h"
#include "client/render/cue_pose.h"
#include "game/loaded_table.h"
#include "protocol/shot_request.h"

namespace pool::ui {

/// The aim `shot` was released with (its power from its speed) and the cue ball it strikes: the
/// ball in hand it places, else `cue_ball`.
std::pair<app::AimState, Eigen::Vector3d> releasedAim(const protocol::ShotRequest& shot,
                                                      const Eigen::Vector3d& cue_ball,
                                                      const game::LoadedTable& table);

/// The cue of another shooter's aim, at its cue ball on the cloth of `table`.
render::CueAim followedCue(const app::FollowedAim& followed, const game::LoadedTable& table);

/// The cue going through after a shot: its aim at release and when.
class CueStroke {
 public:
  /// The stroke of a cue released at `aim` starts at `now` (s).
  void start(const render::CueAim& aim, double now) { stroke_ = Stroke{aim, now}; }
  /// The stroke's cue at `now`; none once it is over (then it is forgotten).
  std::optional<render::CueAim> at(double now);
  bool active() const { return stroke_.has_value(); }

 private:
  struct Stroke {
    render::CueAim aim;
    double start = 0.0;
  };
  std::optional<Stroke> stroke_;
};

}  // namespace pool::ui
