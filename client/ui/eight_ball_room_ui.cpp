// The Magic Eight Ball room's panel.
#include "client/ui/eight_ball_room_ui.h"

#include <imgui.h>

#include "client/room/magic_eight_ball.h"

namespace pool::ui {

bool drawEightBallRoom(EightBallRoomState& state) {
  bool stay = true;
  const ImGuiViewport* screen = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(screen->WorkSize.x * 0.5f, screen->WorkSize.y * 0.85f),
                          ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::Begin("The Magic Eight Ball", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::TextUnformatted("Ask the eight ball a question:");
  char buffer[256] = {};
  state.question.copy(buffer, sizeof buffer - 1);
  const bool entered =
      ImGui::InputText("##question", buffer, sizeof buffer, ImGuiInputTextFlags_EnterReturnsTrue);
  state.question = buffer;
  ImGui::SameLine();
  if (ImGui::Button("Ask") || entered) {
    // A blank question is refused by the ball itself: nothing changes.
    if (auto said = room::answer(state.question, ++state.asked)) state.answer = *said;
  }
  if (!state.answer.empty()) ImGui::Text("The eight ball says: %s", state.answer.c_str());
  if (ImGui::Button("Back to the table")) stay = false;
  ImGui::End();
  return stay;
}

}  // namespace pool::ui
