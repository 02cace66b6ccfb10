// The EGL context host: Mesa's surfaceless platform, no window and no display server; frames
// go only to the FBO. Also picks the host for the current environment.
#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <glad/gl.h>

#include <cstdlib>
#include <stdexcept>

#include "client/render/gl_host.h"

namespace pool::render {

namespace {

class EglHost final : public GlHost {
 public:
  EglHost() {
    const auto get_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
        eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (!get_display) throw std::runtime_error("EGL lacks eglGetPlatformDisplayEXT");
    display_ = get_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major = 0, minor = 0;
    if (display_ == EGL_NO_DISPLAY || eglInitialize(display_, &major, &minor) != EGL_TRUE) {
      throw std::runtime_error("no EGL surfaceless display (Mesa's EGL_MESA_platform_surfaceless)");
    }
    context_ = createContext();
    if (eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_) != EGL_TRUE ||
        gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress)) == 0) {
      release();
      throw std::runtime_error("glad could not load OpenGL 3.3 through EGL");
    }
  }
  ~EglHost() override { release(); }
  EglHost(const EglHost&) = delete;
  EglHost& operator=(const EglHost&) = delete;

  void endFrame() override {}
  std::string name() const override { return "egl-surfaceless"; }

 private:
  EGLContext createContext() {
    // The default surface type (window) does not exist on this platform: ask for pbuffers.
    const EGLint config_attributes[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE,
                                        EGL_OPENGL_BIT, EGL_NONE};
    EGLConfig config = nullptr;
    EGLint configs = 0;
    if (eglChooseConfig(display_, config_attributes, &config, 1, &configs) != EGL_TRUE ||
        configs < 1 || eglBindAPI(EGL_OPENGL_API) != EGL_TRUE) {
      eglTerminate(display_);
      throw std::runtime_error("EGL has no desktop OpenGL config");
    }
    const EGLint context_attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                                         3,
                                         EGL_CONTEXT_MINOR_VERSION,
                                         3,
                                         EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                         EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                         EGL_NONE};
    EGLContext context = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attributes);
    if (context == EGL_NO_CONTEXT) {
      eglTerminate(display_);
      throw std::runtime_error("EGL could not create an OpenGL 3.3 core context");
    }
    return context;
  }

  void release() {
    eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
    eglTerminate(display_);
  }

  EGLDisplay display_ = EGL_NO_DISPLAY;
  EGLContext context_ = EGL_NO_CONTEXT;
};

}  // namespace

std::unique_ptr<GlHost> openEglHost() {
  return std::make_unique<EglHost>();
}

std::unique_ptr<GlHost> openGlHost(int width, int height) {
  const char* display = std::getenv("DISPLAY");
  if (!display || !*display) return openEglHost();
  try {
    return openGlfwHost(width, height);
  } catch (const std::runtime_error& glfw) {
    try {
      return openEglHost();
    } catch (const std::runtime_error& egl) {
      throw std::runtime_error(std::string(glfw.what()) + "; " + egl.what());
    }
  }
}

}  // namespace pool::render
