// The window's 3-D scene: a frame's view handed to the renderer, or the Magic Eight Ball room.
#pragma once

#include <memory>
#include <optional>
#include <string>

#include "client/app/camera_rig.h"
#include "client/render/eight_ball_room.h"
#include "client/render/render_options.h"
#include "client/render/renderer.h"
#include "client/render/scene.h"
#include "client/ui/window_frame_view.h"

namespace pool::ui {

/// The table's renderer, the room's (made on the first visit) and the drawing quality. Needs the
/// window's OpenGL context.
class WindowScene {
 public:
  explicit WindowScene(const render::Scene& scene);

  /// Draws with the preset `chosen` (auto, full or light) from the next frame on; returns the
  /// note that says which.
  std::string applyQuality(const std::string& chosen);
  render::Quality quality() const { return quality_; }
  /// "full" or "light".
  const char* qualityName() const;

  /// Hands `frame` to the renderer: the balls, the overlay, the cue and its ghost ball, the
  /// switches at the quality; the camera of `rig` follows the chased ball and keeps the aiming
  /// view above a local cue.
  void show(const FrameView& frame, app::CameraRig& rig);
  /// Draws the table as shown into the window's framebuffer from `camera`.
  void drawTable(const render::Camera& camera, int width, int height) const;
  /// Draws the Magic Eight Ball room into the window's framebuffer, `answer` on its triangle.
  void drawRoom(const render::RenderOptions& switches, int width, int height,
                const std::string& answer);
  /// The cue as drawn; none when no cue is shown or it could not be placed.
  const std::optional<render::CuePlacement>& cue() const { return renderer_->cue(); }
  /// Draws `scene`'s table from now on (a match on another table: three-cushion's carom table);
  /// the quality stays as chosen.
  void setTable(const render::Scene& scene);

 private:
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<render::EightBallRoom> room_;
  render::Quality quality_ = render::Quality::Full;
  std::string gl_renderer_;  ///< GL_RENDERER, which "auto" quality reads
};

}  // namespace pool::ui
