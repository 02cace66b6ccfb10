// GLFW's key codes and modifier bits as the controls' keys.
#pragma once

#include <optional>

#include "client/app/input.h"

namespace pool::ui {

/// The controls' key for a GLFW key code, if it is one of them.
std::optional<app::Key> keyOf(int glfw_key);
/// GLFW modifier bits as Mods.
app::Mods modsOf(int glfw_mods);

}  // namespace pool::ui
