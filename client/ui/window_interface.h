// The window's interface over the scene (Dear ImGui): the lobby, the HUD or the room.
#pragma once

#include <string>
#include <vector>

#include "client/ui/window_parts.h"

namespace pool::ui {

/// Draws the interface each frame and carries out the player's choices.
class WindowInterface {
 public:
  /// `json`: the HUD's texts are printed whenever they change; `hotseat`: two seats on this
  /// screen.
  WindowInterface(bool json, bool hotseat) : json_(json), hotseat_(hotseat) {}

  /// Draws this frame's interface at `now` (s) over the scene just drawn; `placement_problem`:
  /// why the cue ball in hand cannot go where it is (empty: it can).
  void draw(const WindowParts& w, const std::string& placement_problem, double now);

 private:
  void drawLobbyScreen(const WindowParts& w);
  void drawMatchHud(const WindowParts& w, const std::string& placement_problem, double now);

  bool json_;
  bool hotseat_;
  std::vector<std::string> hud_texts_;  ///< the HUD's texts of the last frame (--json)
};

}  // namespace pool::ui
