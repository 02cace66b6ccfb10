// The window's HUD over the aim scene of --screenshot: a player's turn in an 8-ball match, laid
// out by Dear ImGui as the window lays it out, then drawn over each frame.
#pragma once

#include <deque>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "client/app/clear_area.h"
#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/net/match_types.h"

namespace pool::ui {

/// A Dear ImGui context of its own for one screenshot (made in the constructor, gone with it).
class AimHud {
 public:
  /// Lays the HUD out for a `width` × `height` image with `controls` aiming (its Shot pane).
  AimHud(int width, int height, const app::Controls& controls);
  ~AimHud();
  AimHud(const AimHud&) = delete;
  AimHud& operator=(const AimHud&) = delete;

  /// The standing panes' rectangles as laid out (pixels from the top-left corner).
  const std::vector<app::ScreenRect>& standing() const { return standing_; }
  /// Draws the HUD over the frame in the current OpenGL context (its objects made on the first
  /// frame and freed on the `last`).
  void draw(bool last);
  /// Every pane drawn: [{"name", "rect": [x0, y0, x1, y1]}], pixels from the top-left corner.
  nlohmann::json panesJson() const;

 private:
  /// The image's size and scale for the next frame.
  void prepare() const;
  /// The HUD's panes, between NewFrame and Render.
  void frame();

  int width_;
  int height_;
  const app::Controls& controls_;
  client::MatchView view_;
  std::deque<app::SessionNote> notes_;
  std::deque<std::string> log_;
  std::vector<app::ScreenRect> standing_;
  nlohmann::json panes_ = nlohmann::json::array();
  bool gl_ = false;
};

}  // namespace pool::ui
