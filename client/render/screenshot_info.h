// The screenshot's JSON sidecar: image size, camera and the balls as drawn, so a test can project
// each ball with the same camera and look at the pixels there.
#pragma once

#include <string>
#include <vector>

#include "client/render/renderer.h"

namespace pool::render {

/// {"width", "height", "camera": {"eye", "target", "fov_y_deg"}, "ball_radius",
///  "balls": [{"id", "pos": [x, y, z], "pocketed"}]} (table frame, metres).
std::string screenshotInfoJson(const Camera& camera, int width, int height, double ball_radius,
                               const std::vector<SceneBall>& balls);

}  // namespace pool::render
