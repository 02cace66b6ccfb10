// An offscreen OpenGL 3.3 core context: a hidden GLFW window and a colour+depth framebuffer object.
#pragma once

#include <cstdint>
#include <vector>

struct GLFWwindow;

namespace pool::render {

/// Owns a hidden GLFW window (for the context) and an FBO of the given size. Throws
/// std::runtime_error when GLFW, the context, the loader or the framebuffer fail.
class OffscreenContext {
 public:
  OffscreenContext(int width, int height);
  ~OffscreenContext();
  OffscreenContext(const OffscreenContext&) = delete;
  OffscreenContext& operator=(const OffscreenContext&) = delete;

  /// Makes the FBO the draw target and sets the viewport to its size.
  void bind() const;
  /// RGB bytes of the FBO, top row first (read before `endFrame`).
  std::vector<std::uint8_t> readRgb() const;
  /// Swaps the window's buffers and polls events.
  void endFrame() const;

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void createFramebuffer();

  int width_;
  int height_;
  GLFWwindow* window_ = nullptr;
  unsigned fbo_ = 0;
  unsigned colour_ = 0;
  unsigned depth_ = 0;
};

}  // namespace pool::render
