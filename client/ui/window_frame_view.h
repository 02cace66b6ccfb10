// One frame's view model: what the window draws and reports this frame, read once.
#pragma once

#include <Eigen/Core>
#include <glm/glm.hpp>
#include <optional>
#include <string>
#include <vector>

#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/render/cue_pose.h"
#include "client/render/overlay_lines.h"
#include "client/render/render_options.h"
#include "client/ui/window_log.h"
#include "client/ui/window_stroke.h"
#include "client/ui/window_turn.h"
#include "game/loaded_table.h"
#include "physics/ball.h"

namespace pool::ui {

/// The frame's scene and facts, filled once a frame and then handed to the renderer and the log.
struct FrameView {
  int width = 0;  ///< the framebuffer, pixels
  int height = 0;
  bool replay = false;       ///< the instant replay or a stored shot is shown: the balls only
  bool balls_known = false;  ///< false: no state yet (the renderer keeps its balls)
  std::vector<physics::Ball> shown;       ///< the balls as drawn
  std::optional<Eigen::Vector3d> chased;  ///< the cue ball the watching view follows
  std::vector<render::OverlayLine> overlay;
  /// Why the cue ball in hand cannot go where it is (empty: it can); none during a replay.
  std::optional<std::string> placement_problem;
  std::optional<render::CueAim> cue;
  std::optional<glm::vec3> ghost;  ///< the ghost ball at the predicted first contact
  /// The points of this screen's shot no lamp shade may hide: the cue ball, and the object ball
  /// and the pocket it heads for where the aim has them.
  std::vector<glm::vec3> keep_clear;
  /// Whose cue: "local" (this screen's aim, the aiming view kept above it), "remote" (a live
  /// aim), "stroke" (the cue going through after a shot), or empty (none).
  std::string cue_source;
  render::RenderOptions switches;  ///< the drawing's switches (the quality preset not applied)
  /// The frame's --log-frames line as the session and the controls tell it (the camera and the
  /// pixels are added once drawn).
  DrawnFrame facts;
};

/// What a frame's view is read from.
struct FrameSources {
  app::MatchSession& session;
  app::Controls& controls;
  TurnDesk& turn;
  CueStroke& stroke;
  const game::LoadedTable& table;
  bool follow_cue = false;  ///< the watching view follows the cue ball while the balls run
};

/// The frame at `now` (s) on a `width` × `height` framebuffer: a stored shot's replay in the
/// lobby, the instant replay while one shows, else the match's balls with the cue ball held or
/// placed, the overlay and the cue.
FrameView viewFrame(const FrameSources& from, double now, int width, int height);

}  // namespace pool::ui
