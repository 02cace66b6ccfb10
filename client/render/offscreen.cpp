// Hidden GLFW window plus FBO; pixels are read back from the FBO before the buffers are swapped.
#include "client/render/offscreen.h"

// clang-format off
#include <glad/gl.h>
#include <GLFW/glfw3.h>
// clang-format on

#include <cstring>
#include <stdexcept>
#include <string>

namespace pool::render {

namespace {

GLFWwindow* openHiddenWindow(int width, int height) {
  if (glfwInit() != GLFW_TRUE) throw std::runtime_error("glfwInit failed (is DISPLAY set?)");
  glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(width, height, "pool-client", nullptr, nullptr);
  if (!window) {
    glfwTerminate();
    throw std::runtime_error("no OpenGL 3.3 core context");
  }
  glfwMakeContextCurrent(window);
  if (gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)) == 0) {
    glfwDestroyWindow(window);
    glfwTerminate();
    throw std::runtime_error("glad could not load OpenGL 3.3");
  }
  return window;
}

}  // namespace

OffscreenContext::OffscreenContext(int width, int height)
    : width_(width), height_(height), window_(openHiddenWindow(width, height)) {
  createFramebuffer();
}

OffscreenContext::~OffscreenContext() {
  glDeleteFramebuffers(1, &fbo_);
  glDeleteRenderbuffers(1, &colour_);
  glDeleteRenderbuffers(1, &depth_);
  glfwDestroyWindow(window_);
  glfwTerminate();
}

void OffscreenContext::createFramebuffer() {
  glGenFramebuffers(1, &fbo_);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo_);
  glGenRenderbuffers(1, &colour_);
  glBindRenderbuffer(GL_RENDERBUFFER, colour_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour_);
  glGenRenderbuffers(1, &depth_);
  glBindRenderbuffer(GL_RENDERBUFFER, depth_);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, width_, height_);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth_);
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    throw std::runtime_error("framebuffer incomplete: " + std::to_string(status));
  }
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
  glfwSwapBuffers(window_);
  glfwPollEvents();
}

}  // namespace pool::render
