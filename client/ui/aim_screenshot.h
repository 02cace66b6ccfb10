// The aim scene of --screenshot: the racked table seen from the aiming view, with the cue placed by
// the shot's aim, tip, elevation and power and the ghost ball at the first contact.
#pragma once

#include "client/app/aim.h"
#include "client/render/cue_pose.h"
#include "client/render/screenshot.h"

namespace pool::ui {

/// The renderer's cue for the aim `aim` of the cue ball at `cue_ball` (table frame, m).
render::CueAim cueAimOf(const app::AimState& aim, const Eigen::Vector3d& cue_ball);

/// Renders the racked 9-ft table from behind the cue ball (the window's aiming camera, raised to
/// options.aim.camera_elevation_deg if given) and writes the PNG and the sidecar. Returns the
/// process exit code; errors go to stderr as one line.
int runAimScreenshot(const render::ScreenshotOptions& options);

}  // namespace pool::ui
