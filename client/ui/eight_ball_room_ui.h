// The Magic Eight Ball room's interface (Dear ImGui): the winner types a question and the giant
// 8-ball answers. The room's 3-D scene and the answer list belong to the scene side.
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

/// The answer to `question`. MERGE: replace with room::answer(question, seed) from
/// client/room/magic_eight_ball.h once it exists (the scene side writes it); this stand-in only
/// keeps the room usable until then.
std::string roomAnswer(const std::string& question, std::uint64_t seed);

}  // namespace pool::ui
