// Uploads coverage bitmaps into R8 textures.
#include "client/render/texture.h"

#include <glad/gl.h>

namespace pool::render {

GpuTexture::GpuTexture(const TextBitmap& bitmap, Edges edges) : edges_(edges) {
  glGenTextures(1, &id_);
  upload(bitmap);
}

GpuTexture::~GpuTexture() {
  glDeleteTextures(1, &id_);
}

void GpuTexture::upload(const TextBitmap& bitmap) {
  glBindTexture(GL_TEXTURE_2D, id_);
  glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
  glTexImage2D(GL_TEXTURE_2D, 0, GL_R8, bitmap.width, bitmap.height, 0, GL_RED, GL_UNSIGNED_BYTE,
               bitmap.coverage.data());
  // The tiling noise is sampled over most of the frame (felt, wood, floor): one mip level per
  // fragment costs a software renderer far less than blending two, and its faint texture shows
  // no seam between levels. The number atlas blends them (small on screen, sharp edges).
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER,
                  edges_ == Edges::Repeat ? GL_LINEAR_MIPMAP_NEAREST : GL_LINEAR_MIPMAP_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  const GLint wrap = edges_ == Edges::Repeat ? GL_REPEAT : GL_CLAMP_TO_EDGE;
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, wrap);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, wrap);
  glGenerateMipmap(GL_TEXTURE_2D);
}

void GpuTexture::bind(int unit) const {
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, id_);
}

}  // namespace pool::render
