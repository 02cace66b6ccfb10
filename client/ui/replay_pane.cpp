// The stored shot's replay pane: its lines and its buttons.
#include "client/ui/replay_pane.h"

#include <imgui.h>

namespace pool::ui {
namespace {

/// A button that does nothing (greyed) when `enabled` is false.
bool paneButton(const char* label, bool enabled) {
  if (!enabled) ImGui::BeginDisabled();
  const bool pressed = ImGui::Button(label);
  if (!enabled) ImGui::EndDisabled();
  return pressed && enabled;
}

}  // namespace

std::vector<std::string> ReplayPaneLines::all() const {
  std::vector<std::string> lines = above;
  lines.insert(lines.end(), below.begin(), below.end());
  return lines;
}

ReplayPaneLines replayPaneLines(const app::StoredReplay& stored, const std::string& outcome) {
  ReplayPaneLines lines;
  if (const protocol::HistoryShot* shot = stored.shown()) {
    lines.above.push_back(app::storedShotTitle(*shot));
    const auto name = [&](std::size_t s) {
      return shot->players[s].empty() ? "Player " + std::to_string(s + 1) : shot->players[s];
    };
    lines.above.push_back(name(0) + " v " + name(1) + ", " + rules::toString(shot->game) + " on " +
                          shot->table);
  }
  if (stored.waiting() && stored.problem().empty()) {
    lines.above.push_back("asking the server of " + stored.match() + " for " +
                          (stored.wanted() == 0 ? std::string("its last shot")
                                                : "shot " + std::to_string(stored.wanted())) +
                          "...");
  }
  if (!stored.problem().empty()) lines.below.push_back(stored.problem());
  if (!outcome.empty()) lines.below.push_back(outcome);
  return lines;
}

std::optional<ReplayAction> drawReplayPane(const app::StoredReplay& stored,
                                           const ReplayPaneLines& lines) {
  std::optional<ReplayAction> action;
  const ImGuiViewport* screen = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(screen->WorkPos.x + screen->WorkSize.x * 0.5f, screen->WorkPos.y + 8.0f),
      ImGuiCond_Always, ImVec2(0.5f, 0.0f));
  ImGui::Begin("Replay", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  for (const std::string& line : lines.above) ImGui::TextUnformatted(line.c_str());
  const protocol::HistoryShot* shot = stored.shown();
  if (paneButton("Previous", stored.hasPrevious())) action = ReplayAction::Previous;
  ImGui::SameLine();
  if (paneButton("Next", stored.hasNext())) action = ReplayAction::Next;
  ImGui::SameLine();
  if (paneButton("Play again", shot != nullptr)) action = ReplayAction::Again;
  ImGui::SameLine();
  if (paneButton("Export as a scenario", shot && shot->shoots)) action = ReplayAction::Export;
  ImGui::SameLine();
  if (ImGui::Button("Back to the lobby")) action = ReplayAction::Back;
  for (const std::string& line : lines.below) ImGui::TextUnformatted(line.c_str());
  ImGui::End();
  return action;
}

}  // namespace pool::ui
