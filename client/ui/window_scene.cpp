// The window's 3-D scene: the renderer fed from a frame's view, and the Eight Ball room.
#include "client/ui/window_scene.h"

#include <glad/gl.h>

#include "client/ui/scene_convert.h"

namespace pool::ui {
namespace {

/// Draws into the window's own framebuffer, all of it.
void bindWindowFramebuffer(int width, int height) {
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, width, height);
}

}  // namespace

WindowScene::WindowScene(const render::Scene& scene)
    : renderer_(std::make_unique<render::Renderer>(scene)) {
  // Under a software renderer the light preset keeps the frame budget.
  const GLubyte* gl_renderer = glGetString(GL_RENDERER);
  gl_renderer_ = gl_renderer ? reinterpret_cast<const char*>(gl_renderer) : "";
}

void WindowScene::setTable(const render::Scene& scene) {
  renderer_ = std::make_unique<render::Renderer>(scene);
}

std::string WindowScene::applyQuality(const std::string& chosen) {
  const auto setting = render::parseQualitySetting(chosen).value_or(render::QualitySetting::Auto);
  quality_ = render::resolveQuality(setting, gl_renderer_);
  return std::string("drawing quality: ") + qualityName() + " (" + chosen + ")";
}

const char* WindowScene::qualityName() const {
  return render::qualityName(quality_);
}

void WindowScene::show(const FrameView& frame, app::CameraRig& rig) {
  if (frame.balls_known) renderer_->setBalls(sceneBalls(frame.shown));
  rig.chase(frame.chased);
  renderer_->setOverlay(frame.overlay);
  renderer_->setCue(frame.cue);
  renderer_->setGhost(frame.ghost);
  renderer_->setKeepClear(frame.keep_clear);
  if (const auto& cue = renderer_->cue(); cue && frame.cue_source == "local") {
    rig.keepAimAbove(cue->drawn_elevation + app::kEyeOverCue);
  }
  renderer_->setOptions(render::withQuality(frame.switches, quality_));
}

void WindowScene::drawTable(const render::Camera& camera, int width, int height) const {
  bindWindowFramebuffer(width, height);
  renderer_->draw(camera, width, height);
}

void WindowScene::drawRoom(const render::RenderOptions& switches, int width, int height,
                           const std::string& answer) {
  bindWindowFramebuffer(width, height);
  if (!room_) room_ = std::make_unique<render::EightBallRoom>();
  room_->setOptions(switches);
  room_->draw(render::EightBallRoom::defaultCamera(), width, height, answer);
}

}  // namespace pool::ui
