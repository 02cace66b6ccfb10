// Renderbuffer storage and attachment for the offscreen and scaled targets (multisampled too).
#include "client/render/framebuffer.h"

#include <glad/gl.h>

#include <algorithm>
#include <stdexcept>
#include <string>

namespace pool::render {

void attachColourAndDepth(unsigned colour, unsigned depth, int width, int height, int samples) {
  GLint most = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &most);
  const int n = samples > 1 ? std::min(samples, static_cast<int>(most)) : 0;
  glBindRenderbuffer(GL_RENDERBUFFER, colour);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, n, GL_RGBA8, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorageMultisample(GL_RENDERBUFFER, n, GL_DEPTH_COMPONENT24, width, height);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("framebuffer incomplete: " + std::to_string(status));
  }
}

}  // namespace pool::render
