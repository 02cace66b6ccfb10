// The screenshot's JSON sidecar: image size, camera (and its matrices), the balls, the cue's tip
// and butt, the ghost ball, each lamp's pool of light and each diamond as drawn, each with its
// pixel, so a test can check the picture against positions it computes itself.
#pragma once

#include <string>

#include "client/render/renderer.h"

namespace pool::render {

/// {"width", "height", "camera": {"eye", "target", "up", "fov_y_deg", "view", "projection"},
///  "ball_radius", "balls": [{"id", "pos", "pocketed"}],
///  "cue": {"tip": P, "butt": P, "drawn_elevation_deg"} (when shown), "ghost": P (when shown),
///  "lamps": [{"light": P, "pool": P, "opacity"}], "diamonds": [P]}
/// where P = {"pos": [x, y, z] (table frame, m), "px": [x, y] (pixels from the top-left)} and the
/// matrices are 16 numbers each, column after column (OpenGL's order).
std::string screenshotInfoJson(const Camera& camera, int width, int height,
                               const Renderer& renderer, double ball_radius,
                               const pool::table::TableGeometry& geometry);

}  // namespace pool::render
