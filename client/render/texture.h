// A single-channel OpenGL texture uploaded from a coverage bitmap.
#pragma once

#include "client/render/text_bitmap.h"

namespace pool::render {

/// An R8 texture with mipmapped linear filtering; its edges clamp, or wrap for a tiling image.
/// Needs a current GL context.
class GpuTexture {
 public:
  enum class Edges { Clamp, Repeat };
  explicit GpuTexture(const TextBitmap& bitmap, Edges edges = Edges::Clamp);
  ~GpuTexture();
  GpuTexture(const GpuTexture&) = delete;
  GpuTexture& operator=(const GpuTexture&) = delete;

  /// Replaces the contents (any size).
  void upload(const TextBitmap& bitmap);
  /// Binds it to texture unit `unit`.
  void bind(int unit) const;

 private:
  unsigned id_ = 0;
  Edges edges_;
};

}  // namespace pool::render
