// The screenshot's JSON sidecar: image size, camera (and its matrices), the balls, the cue's tip
// and butt, the ghost ball, each lamp's pool of light and each diamond as drawn, each with its
// pixel, so a test can check the picture against positions it computes itself.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "client/render/renderer.h"

namespace pool::render {

/// {"width", "height", "camera": {"eye", "target", "up", "fov_y_deg", "view", "projection"},
///  "ball_radius", "balls": [{"id", "pos", "pocketed"}],
///  "cue": {"tip": P, "butt": P, "drawn_elevation_deg"} (when shown), "ghost": P (when shown),
///  "lamps": [{"light": P, "pool": P, "opacity"}], "diamonds": [P]}
/// where P = {"pos": [x, y, z] (table frame, m), "px": [x, y] (pixels from the top-left; null
/// for a point behind the camera), "on_screen": whether it is drawn inside the image} and the
/// matrices are 16 numbers each, column after column (OpenGL's order).
std::string screenshotInfoJson(const Camera& camera, int width, int height,
                               const Renderer& renderer, double ball_radius,
                               const pool::table::TableGeometry& geometry);

/// P above for the point `p` seen by `camera` in a `width` × `height` image.
nlohmann::json pointJson(const Camera& camera, int width, int height, glm::vec3 p);

/// The Magic Eight Ball room's sidecar: {"width", "height", "camera": as above, "eight_ball":
/// {"centre": P, "radius", "window": P (its answer window's centre), "answer"}}.
std::string eightBallInfoJson(const Camera& camera, int width, int height, glm::vec3 centre,
                              float radius, glm::vec3 window, const std::string& answer);

}  // namespace pool::render
