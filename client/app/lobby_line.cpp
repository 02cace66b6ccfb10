// The lobby's words for one match: players and ratings, the score, the rack and the shot count.
#include "client/app/lobby_line.h"

#include "client/app/scoreboard.h"

namespace pool::app {
namespace {

std::string pair(const std::array<int, 2>& two) {
  return std::to_string(two[0]) + "-" + std::to_string(two[1]);
}

}  // namespace

std::string lobbyPlayers(const client::LobbyEntry& entry) {
  std::string text;
  for (std::size_t s = 0; s < 2; ++s) {
    if (s == 1) text += " vs ";
    const std::string& name = entry.players[s];
    if (name.empty()) {
      text += "-";
      continue;
    }
    text += name;
    if (entry.ratings[s] > 0) text += " (" + std::to_string(entry.ratings[s]) + ")";
  }
  return text;
}

std::string lobbyProgress(const client::LobbyEntry& entry) {
  const std::string shots = "shot " + std::to_string(entry.shot_number);
  if (entry.settings.practice) return "practice, " + shots;
  if (entry.rack == 0) return "";
  const std::string word = rackWord(entry.settings.game);
  std::string text =
      word + "s " + pair(entry.racks_won) + ", " + word + " " + std::to_string(entry.rack);
  if (!rules::isPool(entry.settings.game)) text += " " + pair(entry.rack_points);
  return text + ", " + shots;
}

}  // namespace pool::app
