// The lobby screen (Dear ImGui): every open match of every server, to join, start or watch.
#pragma once

#include <optional>
#include <string>

#include "client/net/lobby.h"

namespace pool::ui {

/// What the player picked in the lobby.
struct LobbyChoice {
  enum class Kind : std::uint8_t { Play, Spectate, Cancel } kind = Kind::Play;
  std::string match;  ///< empty: the first free table (Play) or the first match in play
                      ///< (Spectate); Cancel: stop waiting for a match to join
};

/// Draws the lobby for this frame; `joining` greys the buttons while answers are pending.
std::optional<LobbyChoice> drawLobby(const client::Lobby& lobby, bool joining, bool hotseat);

}  // namespace pool::ui
