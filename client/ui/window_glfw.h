// The window's GLFW window with an OpenGL 3.3 core context, and Dear ImGui on top of it.
#pragma once

struct GLFWwindow;

namespace pool::ui {

/// GLFW and a visible window with an OpenGL 3.3 core context (vsync on); ImGui once started.
class GlfwWindow {
 public:
  /// Throws std::runtime_error when there is no display, no such context or no OpenGL loader.
  GlfwWindow(int width, int height);
  ~GlfwWindow();
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  /// Starts ImGui on the window; ImGui chains to the callbacks installed before this call.
  void startImGui();
  /// The GLFW window.
  GLFWwindow* get() const { return window_; }
  /// Full screen on the primary monitor at its mode, or back to the window it was.
  void setFullScreen(bool full);
  bool fullScreen() const { return full_screen_; }

 private:
  GLFWwindow* window_ = nullptr;
  bool full_screen_ = false;
  int windowed_[4] = {0, 0, 0, 0};  ///< x, y, width, height before going full screen
  bool imgui_ = false;
};

}  // namespace pool::ui
