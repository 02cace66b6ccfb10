// The Magic Eight Ball room's interface (Dear ImGui): the winner types a question and the giant
// 8-ball answers (client/room holds the twenty answers, client/render draws the room).
#pragma once

#include <cstdint>
#include <string>

namespace pool::ui {

/// The room's state between frames.
struct EightBallRoomState {
  std::string question;
  std::string answer;  ///< empty until a question is asked
  std::uint64_t asked = 0;
};

/// Draws the room's panel; returns false when the player leaves the room.
bool drawEightBallRoom(EightBallRoomState& state);

}  // namespace pool::ui
