// An offscreen colour and depth target the scene is drawn into at a fraction of the window's
// resolution, then stretched onto the window's framebuffer (the light preset's render scale), or
// at its resolution with several samples a pixel, then resolved onto it (the high preset's
// anti-aliasing).
#pragma once

namespace pool::render {

/// Needs a current OpenGL 3.3 core context while alive.
class ScaledTarget {
 public:
  ScaledTarget() = default;
  ~ScaledTarget();
  ScaledTarget(const ScaledTarget&) = delete;
  ScaledTarget& operator=(const ScaledTarget&) = delete;

  /// Binds the target at `width` × `height` with `samples` a pixel (0 or 1: one; made or
  /// resized as needed) and its viewport; remembers the framebuffer bound before.
  void begin(int width, int height, int samples = 0);
  /// Stretches the target onto the framebuffer bound before begin(), `out_width` ×
  /// `out_height`, linearly filtered (a multisampled target: resolved, at its own size), and
  /// binds that framebuffer and viewport again.
  void end(int out_width, int out_height);

 private:
  unsigned fbo_ = 0, colour_ = 0, depth_ = 0;
  int width_ = 0, height_ = 0, samples_ = 0;
  int previous_ = 0;
};

}  // namespace pool::render
