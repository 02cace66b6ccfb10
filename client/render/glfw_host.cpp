// The GLFW context host: a hidden window whose context renders into our FBO.
// clang-format off
#include <glad/gl.h>
#include <GLFW/glfw3.h>
// clang-format on

#include <stdexcept>

#include "client/render/gl_host.h"

namespace pool::render {

namespace {

class GlfwHost final : public GlHost {
 public:
  GlfwHost(int width, int height) {
    if (glfwInit() != GLFW_TRUE) throw std::runtime_error("glfwInit failed (is DISPLAY set?)");
    glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, "pool-client", nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw std::runtime_error("no OpenGL 3.3 core context from GLFW");
    }
    glfwMakeContextCurrent(window_);
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)) == 0) {
      glfwDestroyWindow(window_);
      glfwTerminate();
      throw std::runtime_error("glad could not load OpenGL 3.3 through GLFW");
    }
  }
  ~GlfwHost() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  GlfwHost(const GlfwHost&) = delete;
  GlfwHost& operator=(const GlfwHost&) = delete;

  void endFrame() override {
    glfwSwapBuffers(window_);
    glfwPollEvents();
  }
  std::string name() const override { return "glfw"; }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

std::unique_ptr<GlHost> openGlfwHost(int width, int height) {
  return std::make_unique<GlfwHost>(width, height);
}

}  // namespace pool::render
