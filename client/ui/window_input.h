// The window's input: GLFW keys, mouse buttons, cursor and scroll wheel into the controls.
#pragma once

#include "client/app/controls.h"

struct GLFWwindow;

namespace pool::ui {

/// Sends `window`'s keys, mouse buttons, cursor moves and scrolling to `controls` (which must
/// outlive the window's callbacks); what ImGui wants for itself stays with ImGui. Install before
/// ImGui starts, so that ImGui chains to these callbacks.
void installInput(GLFWwindow* window, app::Controls& controls);

}  // namespace pool::ui
