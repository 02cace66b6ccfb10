// A single-channel OpenGL texture uploaded from a coverage bitmap.
#pragma once

#include "client/render/text_bitmap.h"

namespace pool::render {

/// An R8 texture with linear filtering and clamped edges; needs a current GL context.
class GpuTexture {
 public:
  explicit GpuTexture(const TextBitmap& bitmap);
  ~GpuTexture();
  GpuTexture(const GpuTexture&) = delete;
  GpuTexture& operator=(const GpuTexture&) = delete;

  /// Replaces the contents (any size).
  void upload(const TextBitmap& bitmap);
  /// Binds it to texture unit `unit`.
  void bind(int unit) const;

 private:
  unsigned id_ = 0;
};

}  // namespace pool::render
