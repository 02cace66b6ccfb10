// Where an offscreen OpenGL 3.3 core context comes from: a hidden GLFW window (X11) or EGL
// surfaceless (Mesa, no display server at all).
#pragma once

#include <memory>
#include <string>

namespace pool::render {

/// Owns a current OpenGL 3.3 core context with the glad loader initialised.
class GlHost {
 public:
  virtual ~GlHost() = default;
  /// Ends a frame (swaps buffers and polls events where there is a window).
  virtual void endFrame() = 0;
  /// "glfw" or "egl-surfaceless".
  virtual std::string name() const = 0;
};

/// A hidden GLFW window of the given size; throws std::runtime_error when it cannot be made.
std::unique_ptr<GlHost> openGlfwHost(int width, int height);
/// An EGL context on Mesa's surfaceless platform (render into an FBO); throws
/// std::runtime_error when EGL or the platform is missing.
std::unique_ptr<GlHost> openEglHost();

/// GLFW when DISPLAY is set (falling back to EGL if GLFW fails), EGL surfaceless otherwise.
/// Throws std::runtime_error naming why each failed.
std::unique_ptr<GlHost> openGlHost(int width, int height);

}  // namespace pool::render
