// A frame as drawn: the cue ball and the cue projected to pixels, the camera as matrices.
#include "client/ui/window_drawn.h"

namespace pool::ui {
namespace {

/// The cue ball of `shown` as drawn: table frame, and pixels when in front of the eye.
void placeCueBallDrawn(DrawnFrame& f, const std::vector<physics::Ball>& shown,
                       const render::Camera& camera) {
  for (const auto& b : shown) {
    if (b.id != physics::kCueBall || !physics::onTable(b.state)) continue;
    f.cue = b.pos;
    const glm::vec3 p = render::projectToPixels(
        camera, f.width, f.height,
        glm::vec3(static_cast<float>(b.pos.x()), static_cast<float>(b.pos.y()),
                  static_cast<float>(b.pos.z())));
    if (p.z >= 0.0f) f.cue_px = Eigen::Vector2d(p.x, p.y);  // not when behind the eye
  }
}

/// The camera's view and projection matrices, column after column.
void putCameraMatrices(DrawnFrame& f, const render::Camera& camera) {
  const glm::mat4 view = render::viewMatrix(camera);
  const glm::mat4 projection =
      render::projectionMatrix(camera, static_cast<float>(f.width) / static_cast<float>(f.height));
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      f.view[static_cast<std::size_t>(4 * c + r)] = view[c][r];
      f.projection[static_cast<std::size_t>(4 * c + r)] = projection[c][r];
    }
  }
}

}  // namespace

DrawnFrame drawnFrame(const FrameView& frame, const render::Camera& camera) {
  DrawnFrame f = frame.facts;
  f.width = frame.width;
  f.height = frame.height;
  placeCueBallDrawn(f, frame.shown, camera);
  putCameraMatrices(f, camera);
  return f;
}

CueStick cueStickOf(const render::CuePlacement& cue, const render::Camera& camera, int width,
                    int height) {
  CueStick s;
  s.tip = {cue.tip.x, cue.tip.y, cue.tip.z};
  s.butt = {cue.butt.x, cue.butt.y, cue.butt.z};
  const glm::vec3 tip = render::projectToPixels(camera, width, height, cue.tip);
  const glm::vec3 butt = render::projectToPixels(camera, width, height, cue.butt);
  s.tip_px = {tip.x, tip.y};
  s.butt_px = {butt.x, butt.y};
  return s;
}

}  // namespace pool::ui
