// An offscreen OpenGL 3.3 core context (GLFW hidden window or EGL surfaceless) and a colour+depth
// framebuffer object.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "client/render/gl_host.h"

namespace pool::render {

/// Owns a context (see openGlHost: GLFW with a display, EGL surfaceless without) and an FBO of the
/// given size. Throws std::runtime_error when the context, the loader or the framebuffer fail.
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
  /// Ends the frame (swaps the hidden window's buffers, if there is one).
  void endFrame() const;
  /// Where the context came from: "glfw" or "egl-surfaceless".
  std::string backend() const { return host_->name(); }

  int width() const { return width_; }
  int height() const { return height_; }

 private:
  void createFramebuffer();

  int width_;
  int height_;
  std::unique_ptr<GlHost> host_;
  unsigned fbo_ = 0;
  unsigned colour_ = 0;
  unsigned depth_ = 0;
};

}  // namespace pool::render
