// The scaled target's framebuffer, resized on demand, and its blit to the window.
#include "client/render/scaled_target.h"

#include <glad/gl.h>

#include "client/render/framebuffer.h"

namespace pool::render {

ScaledTarget::~ScaledTarget() {
  if (fbo_ == 0) return;
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colour_);
  glDeleteRenderbuffers(1, &depth_);
}

void ScaledTarget::begin(int width, int height) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_);
  if (fbo_ == 0) {
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &colour_);
    glGenRenderbuffers(1, &depth_);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  if (width != width_ || height != height_) {
    width_ = width;
    height_ = height;
    attachColourAndDepth(colour_, depth_, width, height);
  }
  glViewport(0, 0, width, height);
}

void ScaledTarget::end(int out_width, int out_height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previous_));
  glBlitFramebuffer(0, 0, width_, height_, 0, 0, out_width, out_height, GL_COLOR_BUFFER_BIT,
                    GL_LINEAR);
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_));
  glViewport(0, 0, out_width, out_height);
}

}  // namespace pool::render
