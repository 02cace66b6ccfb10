// The offscreen FBO on whichever context host is available; pixels are read back from the FBO
// before the frame ends.
#include "client/render/offscreen.h"

#include <glad/gl.h>

#include <cstring>

#include "client/render/framebuffer.h"

namespace pool::render {

OffscreenContext::OffscreenContext(int width, int height)
    : width_(width), height_(height), host_(openGlHost(width, height)) {
  createFramebuffer();
}

OffscreenContext::~OffscreenContext() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colour_);
  glDeleteRenderbuffers(1, &depth_);
}

void OffscreenContext::createFramebuffer() {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &colour_);
  glGenRenderbuffers(1, &depth_);
  attachColourAndDepth(colour_, depth_, width_, height_);
}

void OffscreenContext::bind() const {
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glViewport(0, 0, width_, height_);
}

std::vector<std::uint8_t> OffscreenContext::readRgb() const {
  const auto row = static_cast<std::size_t>(width_) * 3;
  std::vector<std::uint8_t> bottom_up(row * static_cast<std::size_t>(height_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, fbo_);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width_, height_, GL_RGB, GL_UNSIGNED_BYTE, bottom_up.data());
  std::vector<std::uint8_t> top_down(bottom_up.size());
  for (std::size_t y = 0; y < static_cast<std::size_t>(height_); ++y) {
    const std::size_t src = (static_cast<std::size_t>(height_) - 1 - y) * row;
    std::memcpy(top_down.data() + y * row, bottom_up.data() + src, row);
  }
  return top_down;
}

void OffscreenContext::endFrame() const {
  host_->endFrame();
}

}  // namespace pool::render
