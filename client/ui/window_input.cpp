// GLFW callbacks that feed the controls, through the window's user pointer.
#include "client/ui/window_input.h"

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "client/ui/glfw_keys.h"

namespace pool::ui {
namespace {

app::Controls& controlsOf(GLFWwindow* w) {
  return *static_cast<app::Controls*>(glfwGetWindowUserPointer(w));
}

bool imGuiWants(bool keyboard) {
  if (!ImGui::GetCurrentContext()) return false;
  return keyboard ? ImGui::GetIO().WantCaptureKeyboard : ImGui::GetIO().WantCaptureMouse;
}

void onKey(GLFWwindow* win, int key, int, int action, int mods) {
  if (imGuiWants(true)) return;
  const auto k = keyOf(key);
  if (!k || action == GLFW_REPEAT) return;
  if (action == GLFW_PRESS) controlsOf(win).keyDown(*k, modsOf(mods));
  if (action == GLFW_RELEASE) controlsOf(win).keyUp(*k);
}

void onMouseButton(GLFWwindow* win, int button, int action, int mods) {
  // A release always reaches the controls: a drag or stroke begun on the table may end over a pane.
  if (action == GLFW_PRESS && imGuiWants(false)) return;
  if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
  double x = 0, y = 0;
  glfwGetCursorPos(win, &x, &y);
  controlsOf(win).mouseButton(
      button == GLFW_MOUSE_BUTTON_LEFT ? app::MouseButton::Left : app::MouseButton::Right,
      action == GLFW_PRESS, x, y, modsOf(mods));
}

void onCursor(GLFWwindow* win, double x, double y) {
  controlsOf(win).mouseMove(x, y);
}

void onScroll(GLFWwindow* win, double, double dy) {
  if (imGuiWants(false)) return;
  controlsOf(win).scroll(dy);
}

}  // namespace

void installInput(GLFWwindow* window, app::Controls& controls) {
  glfwSetWindowUserPointer(window, &controls);
  glfwSetKeyCallback(window, onKey);
  glfwSetMouseButtonCallback(window, onMouseButton);
  glfwSetCursorPosCallback(window, onCursor);
  glfwSetScrollCallback(window, onScroll);
}

}  // namespace pool::ui
