// The window's capture: the frame just drawn, written to a PNG file.
#pragma once

#include <string>

struct GLFWwindow;

namespace pool::ui {

/// Writes the frame just drawn in `window` (its back buffer, read before the swap) to the PNG
/// file `path`. False when the file could not be written.
bool writeFramePng(GLFWwindow* window, const std::string& path);

}  // namespace pool::ui
