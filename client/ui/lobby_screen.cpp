// Lobby window.
#include "client/ui/lobby_screen.h"

#include <imgui.h>

#include <algorithm>

#include "client/app/lobby_line.h"
#include "client/app/player_columns.h"
#include "client/app/spoken.h"
#include "client/app/tournament_lines.h"
#include "client/bot/ai/bot_level.h"

namespace pool::ui {
namespace {

void tableOptions(TableOptions& options) {
  ImGui::TextUnformatted("A fresh table:");
  ImGui::SameLine();
  for (const rules::GameInfo& game : rules::allGames()) {
    ImGui::SameLine();
    ImGui::RadioButton(game.name, &options.game, game.number);
  }
  if (options.game == rules::gameNumber(rules::Game::ThreeCushion)) {
    ImGui::SetNextItemWidth(160);
    ImGui::SliderInt("points", &options.points, 1, 50);
  }
  // Snooker's race is in frames; a pool race in racks (three-cushion's in games).
  const bool snooker = options.game == rules::gameNumber(rules::Game::Snooker);
  ImGui::SetNextItemWidth(160);
  ImGui::SliderInt(snooker ? "race to (frames)" : "race to", &options.race_to, 1,
                   protocol::kMaxRace);
  ImGui::SameLine();
  ImGui::Checkbox("winner breaks", &options.winner_breaks);
  ImGui::SetNextItemWidth(160);
  ImGui::SliderInt("shot clock, s (0: off)", &options.shot_clock, 0, 120);
  if (options.shot_clock > 0 && options.shot_clock < protocol::kMinShotClock) {
    options.shot_clock = static_cast<int>(protocol::kMinShotClock);
  }
}

/// Every player's rating and statistics, a row per player and game (app::playerColumns).
void drawPlayers(const client::PlayerBook& players) {
  if (players.size() == 0) return;
  if (!ImGui::CollapsingHeader("Players: ratings and statistics", ImGuiTreeNodeFlags_DefaultOpen))
    return;
  const auto& headers = app::playerHeaders();
  if (!ImGui::BeginTable("players", static_cast<int>(headers.size()),
                         ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    return;
  }
  for (const char* h : headers) ImGui::TableSetupColumn(h);
  ImGui::TableHeadersRow();
  for (const protocol::PlayerStats* s : players.records()) {
    ImGui::TableNextRow();
    for (const std::string& text : app::playerColumns(*s)) {
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(text.c_str());
    }
  }
  ImGui::EndTable();
}

/// The matches seen played that have left the lobby: players, how far they went, Replay.
void drawRecent(const std::vector<const client::LobbyEntry*>& recent, bool joining,
                std::optional<LobbyChoice>& choice) {
  if (recent.empty()) return;
  if (!ImGui::CollapsingHeader("Recent matches (finished or closed)",
                               ImGuiTreeNodeFlags_DefaultOpen))
    return;
  for (const client::LobbyEntry* e : recent) {
    ImGui::PushID(e->match.c_str());
    ImGui::Text("%s  %s  %s", e->match.c_str(), app::lobbyPlayers(*e).c_str(),
                app::lobbyProgress(*e).c_str());
    if (!joining) {
      ImGui::SameLine();
      if (ImGui::SmallButton("Replay")) choice = LobbyChoice{LobbyChoice::Kind::Replay, e->match};
    }
    ImGui::PopID();
  }
}

/// A tournament to open: its format, entrants and handicap (its game and race are the fresh
/// table's options above).
void openTournament(TableOptions& options, bool hotseat, std::optional<LobbyChoice>& choice) {
  if (hotseat) return;  // an entrant is one player's key
  if (ImGui::Button("Open a tournament"))
    choice = LobbyChoice{LobbyChoice::Kind::OpenTournament, ""};
  ImGui::SameLine();
  constexpr const char* kFormats[] = {"single elimination", "double elimination", "round robin"};
  for (int f = 0; f < 3; ++f) {
    ImGui::SameLine();
    ImGui::RadioButton(kFormats[f], &options.tournament_format, f);
  }
  ImGui::SameLine();
  // A round robin's every match crosses the wire: 11 entrants play 55 (12 would play 66).
  const int most = options.tournament_format == 2
                       ? protocol::kMaxRoundRobinEntrants
                       : static_cast<int>(protocol::kMaxTournamentEntrants);
  options.tournament_entrants = std::min(options.tournament_entrants, most);
  ImGui::SetNextItemWidth(120);
  ImGui::SliderInt("entrants", &options.tournament_entrants, 3, most);
  ImGui::SameLine();
  ImGui::Checkbox("handicap", &options.handicap);
}

/// The buttons of a tournament taking entries: Enter (until this player is in) and Add a bot.
void entryButtons(const protocol::TournamentView& t, const std::string& me, bool hotseat,
                  std::optional<LobbyChoice>& choice) {
  if (t.phase != protocol::TournamentPhase::Entry) return;
  const bool full = static_cast<int>(t.entrants.size()) >= t.capacity;
  if (t.entrantOf(me) >= 0) {
    ImGui::TextUnformatted("you are in: your matches start here as they come");
  } else if (!full && !hotseat && ImGui::SmallButton("Enter")) {
    choice = LobbyChoice{LobbyChoice::Kind::Enter, t.tournament};
  }
  if (full) return;
  ImGui::SameLine();
  if (ImGui::SmallButton("Add a bot"))
    choice = LobbyChoice{LobbyChoice::Kind::AddBot, t.tournament};
}

/// The tournaments, each a tree of its entrants and its bracket (app::tournament_lines); a match
/// in play has a Watch button, one played or in play a Replay button.
void drawTournaments(const std::map<std::string, protocol::TournamentView>& tournaments,
                     bool joining, bool hotseat, const std::string& me,
                     std::optional<LobbyChoice>& choice) {
  if (tournaments.empty()) return;
  if (!ImGui::CollapsingHeader("Tournaments", ImGuiTreeNodeFlags_DefaultOpen)) return;
  for (const auto& [id, t] : tournaments) {
    ImGui::PushID(id.c_str());
    ImGui::SetNextItemOpen(true, ImGuiCond_Once);
    if (ImGui::TreeNode("tournament", "%s", app::tournamentLine(t).c_str())) {
      if (!joining) entryButtons(t, me, hotseat, choice);
      for (const std::string& line : app::entrantLines(t)) ImGui::BulletText("%s", line.c_str());
      for (const app::BracketLine& line : app::bracketLines(t)) {
        ImGui::TextUnformatted(line.text.c_str());
        if (line.in_play && !joining) {
          ImGui::SameLine();
          ImGui::PushID(line.match.c_str());
          if (ImGui::SmallButton("Watch")) {
            choice = LobbyChoice{LobbyChoice::Kind::Spectate, line.match};
          }
          ImGui::PopID();
        }
        // A match played or in play: its stored shots.
        if (!line.match.empty() && !joining) {
          ImGui::SameLine();
          ImGui::PushID(line.match.c_str());
          if (ImGui::SmallButton("Replay")) {
            choice = LobbyChoice{LobbyChoice::Kind::Replay, line.match};
          }
          ImGui::PopID();
        }
      }
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

}  // namespace

protocol::MatchSettings TableOptions::settings() const {
  protocol::MatchSettings s;
  s.game = rules::gameOfNumber(game).value_or(rules::Game::EightBall);
  s.practice = practice;
  // A practice table of any game, on that game's table; it has no race and no clock.
  if (practice) return s;
  if (s.game == rules::Game::ThreeCushion) s.points = points;
  s.race_to = race_to;
  s.breaks = winner_breaks ? protocol::BreakOrder::Winner : protocol::BreakOrder::Alternate;
  s.shot_clock = shot_clock;
  return s;
}

protocol::TournamentOpening TableOptions::opening() const {
  return {static_cast<protocol::TournamentFormat>(std::clamp(tournament_format, 0, 2)),
          tournament_entrants, handicap};
}

std::optional<LobbyChoice> drawLobby(
    const client::Lobby& lobby, const std::map<std::string, protocol::TournamentView>& tournaments,
    const client::PlayerBook& players, bool joining, bool hotseat, TableOptions& options,
    const std::string& me, const std::vector<const client::LobbyEntry*>& recent) {
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
    if (ImGui::Button(play)) {
      options.practice = false;
      choice = LobbyChoice{LobbyChoice::Kind::Play, ""};
    }
    ImGui::SameLine();
    // At the game picked below: its rack on its table (snooker's, the carom table).
    if (ImGui::Button("Practice at a table of my own")) {
      options.practice = true;
      choice = LobbyChoice{LobbyChoice::Kind::Play, "new"};
    }
    ImGui::SameLine();
    if (ImGui::Button("Watch a match in play"))
      choice = LobbyChoice{LobbyChoice::Kind::Spectate, ""};
    if (!hotseat) {
      if (ImGui::Button("Play the bot")) {
        options.practice = false;
        choice = LobbyChoice{LobbyChoice::Kind::PlayBot, ""};
      }
      for (const int level : {0, 1, 2, 3}) {
        ImGui::SameLine();
        ImGui::RadioButton(bot::toString(static_cast<bot::Level>(level)), &options.bot_level,
                           level);
      }
    }
    tableOptions(options);
    openTournament(options, hotseat, choice);
  }
  ImGui::Separator();
  if (lobby.empty()) ImGui::TextUnformatted("no server found yet (is pool-server running?)");
  if (ImGui::BeginTable("matches", 7, ImGuiTableFlags_Borders | ImGuiTableFlags_RowBg)) {
    for (const char* h : {"match", "table", "phase", "players (rating)", "score", "watching", ""}) {
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
      ImGui::TextUnformatted(app::lobbyPlayers(*e).c_str());
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(app::lobbyProgress(*e).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%u", e->spectators);
      ImGui::TableNextColumn();
      if (joining) continue;
      ImGui::PushID(e->match.c_str());
      // Side by side; the first at the cell's start (a SameLine there would follow the cell
      // before, where the button is clipped away).
      if (e->seats_taken < (hotseat ? 1 : 2)) {
        if (ImGui::SmallButton("Join")) choice = LobbyChoice{LobbyChoice::Kind::Play, e->match};
        ImGui::SameLine();
      }
      if (ImGui::SmallButton("Watch")) choice = LobbyChoice{LobbyChoice::Kind::Spectate, e->match};
      if (e->shot_number > 0) {
        ImGui::SameLine();
        if (ImGui::SmallButton("Replay")) choice = LobbyChoice{LobbyChoice::Kind::Replay, e->match};
      }
      ImGui::PopID();
    }
    ImGui::EndTable();
  }
  drawTournaments(tournaments, joining, hotseat, me, choice);
  drawRecent(recent, joining, choice);
  drawPlayers(players);
  ImGui::End();
  return choice;
}

}  // namespace pool::ui
