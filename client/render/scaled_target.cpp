// The scaled target's framebuffer, resized on demand, and its blit (or resolve) to the window.
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

void ScaledTarget::begin(int width, int height, int samples) {
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &previous_);
  if (fbo_ == 0) {
    glGenFramebuffers(1, &fbo_);
    glGenRenderbuffers(1, &colour_);
    glGenRenderbuffers(1, &depth_);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  samples = samples > 1 ? samples : 0;
  if (width != width_ || height != height_ || samples != samples_) {
    width_ = width;
    height_ = height;
    samples_ = samples;
    attachColourAndDepth(colour_, depth_, width, height, samples);
  }
  glViewport(0, 0, width, height);
}

void ScaledTarget::end(int out_width, int out_height) {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(previous_));
  if (samples_ > 0) {
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, width_, height_, GL_COLOR_BUFFER_BIT,
                      GL_NEAREST);
  } else {
    glBlitFramebuffer(0, 0, width_, height_, 0, 0, out_width, out_height, GL_COLOR_BUFFER_BIT,
                      GL_LINEAR);
  }
  glBindFramebuffer(GL_FRAMEBUFFER, static_cast<GLuint>(previous_));
  glViewport(0, 0, out_width, out_height);
}

}  // namespace pool::render
