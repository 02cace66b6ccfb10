// The window's input script: each frame's scripted key presses into the controls.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "client/app/controls.h"
#include "client/app/input_script.h"
#include "client/app/match_session.h"

namespace pool::ui {

/// The scripted mouse: where it is, and where the cue ball was drawn in the last frame (pixels).
struct ScriptMouse {
  Eigen::Vector2d at = Eigen::Vector2d::Zero();
  bool down = false;  ///< the left button is held (the lobby's buttons see it too)
  std::optional<Eigen::Vector2d> cue_ball;
  std::string capture;  ///< a PNG file to write this frame to (a script's capture step)
};

/// Plays this frame's steps of `script` on `controls`, given whether they can aim and the
/// session's shot number at `at` (s; a stored shot's replay counts as motion until its table is
/// at rest, from the moment it is asked); a capture step leaves its file in `mouse.capture`. True
/// when the script says to quit.
bool playScriptFrame(app::ScriptPlayer& script, app::Controls& controls,
                     const app::MatchSession& session, ScriptMouse& mouse, double at);

}  // namespace pool::ui
