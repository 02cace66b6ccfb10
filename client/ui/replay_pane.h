// The pane of a stored shot's replay (Dear ImGui), in the lobby's stead: which shot of which match,
// who played it and the verdict, and the buttons that walk the shots, play one again, export it.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "client/app/stored_replay.h"

namespace pool::ui {

/// A button of the pane.
enum class ReplayAction : std::uint8_t { Previous, Next, Again, Export, Back };

/// The pane's lines: above its buttons the shot's title (app::storedShotTitle) and its players,
/// game and table, and the shot asked while it is not shown; below them the problem, if any, and
/// `outcome`, the last export's, if any (the buttons stay put when they come and go).
struct ReplayPaneLines {
  std::vector<std::string> above;
  std::vector<std::string> below;
  /// Every line, from the top.
  std::vector<std::string> all() const;
};
ReplayPaneLines replayPaneLines(const app::StoredReplay& stored, const std::string& outcome);

/// Draws the pane for this frame at the top of the screen (the table stays in view) with
/// `lines`; returns the button pressed, if any.
std::optional<ReplayAction> drawReplayPane(const app::StoredReplay& stored,
                                           const ReplayPaneLines& lines);

}  // namespace pool::ui
