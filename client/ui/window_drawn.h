// A frame as drawn: the cue ball, the cue and the camera on screen (scripts, --log-frames).
#pragma once

#include "client/render/camera.h"
#include "client/render/cue_pose.h"
#include "client/ui/window_frame_view.h"
#include "client/ui/window_log.h"

namespace pool::ui {

/// The frame's facts with the cue ball as `camera` drew it (table frame and pixels, not when
/// behind the eye), the camera's matrices and the framebuffer's size.
DrawnFrame drawnFrame(const FrameView& frame, const render::Camera& camera);

/// The drawn cue's tip and butt in the table frame and in pixels.
CueStick cueStickOf(const render::CuePlacement& cue, const render::Camera& camera, int width,
                    int height);

}  // namespace pool::ui
