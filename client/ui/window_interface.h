// The window's interface over the scene (Dear ImGui): the lobby, the HUD or the room.
#pragma once

#include <string>
#include <vector>

#include "client/ui/window_parts.h"
#include "client/ui/window_script.h"

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
  /// A script's mouse (or none): in the lobby it works the buttons in the real mouse's stead.
  void setScriptMouse(const ScriptMouse* mouse) { script_mouse_ = mouse; }

 private:
  void drawLobbyScreen(const WindowParts& w);
  /// A stored shot's replay pane, in the lobby's stead, and its buttons carried out.
  void drawStoredReplay(const WindowParts& w, double now);
  void drawMatchHud(const WindowParts& w, const std::string& placement_problem, double now);

  bool json_;
  bool hotseat_;
  const ScriptMouse* script_mouse_ = nullptr;
  std::vector<std::string> hud_texts_;  ///< the HUD's texts of the last frame (--json)
  std::string export_line_;  ///< what the replay pane's last export did (until another shot)
};

}  // namespace pool::ui
