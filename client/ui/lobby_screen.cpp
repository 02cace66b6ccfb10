// Lobby window.
#include "client/ui/lobby_screen.h"

#include <imgui.h>

#include "client/app/spoken.h"

namespace pool::ui {
namespace {

std::string playersOf(const client::LobbyEntry& e) {
  std::string text;
  for (const auto& p : e.players) text += (text.empty() ? "" : " vs ") + (p.empty() ? "-" : p);
  return text;
}

}  // namespace

std::optional<LobbyChoice> drawLobby(const client::Lobby& lobby, bool joining, bool hotseat) {
  std::optional<LobbyChoice> choice;
  const ImGuiViewport* screen = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(screen->WorkSize.x * 0.5f, screen->WorkSize.y * 0.5f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::Begin("Lobby", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  if (joining) {
    ImGui::TextUnformatted("joining (waiting for a free table or a match in play)...");
    ImGui::SameLine();
    if (ImGui::Button("Cancel")) choice = LobbyChoice{LobbyChoice::Kind::Cancel, ""};
  } else {
    const char* play = hotseat ? "New game: two players here, first free table"
                               : "New game at the first free table";
    if (ImGui::Button(play)) choice = LobbyChoice{LobbyChoice::Kind::Play, ""};
    ImGui::SameLine();
    if (ImGui::Button("Watch a match in play"))
      choice = LobbyChoice{LobbyChoice::Kind::Spectate, ""};
  }
  ImGui::Separator();
  if (lobby.empty()) ImGui::TextUnformatted("no server found yet (is pool-server running?)");
  if (ImGui::BeginTable("matches", 6, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    for (const char* h : {"match", "table", "phase", "players", "watching", ""}) {
      ImGui::TableSetupColumn(h);
    }
    ImGui::TableHeadersRow();
    for (const client::LobbyEntry* e : lobby.entries()) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(e->match.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(e->table.c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(app::spoken(client::toString(e->phase)).c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(playersOf(*e).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%u", e->spectators);
      ImGui::TableNextColumn();
      if (joining) continue;
      ImGui::PushID(e->match.c_str());
      if (e->seats_taken < (hotseat ? 1 : 2) && ImGui::SmallButton("Join")) {
        choice = LobbyChoice{LobbyChoice::Kind::Play, e->match};
      }
      ImGui::SameLine();
      if (ImGui::SmallButton("Watch")) choice = LobbyChoice{LobbyChoice::Kind::Spectate, e->match};
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  ImGui::End();
  return choice;
}

}  // namespace pool::ui
