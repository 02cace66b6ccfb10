// The window's interface: an ImGui frame with the room, the lobby or the HUD, and its choices.
#include "client/ui/window_interface.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "client/ui/pane_rects.h"
#include "client/ui/window_commands.h"
#include "client/ui/window_hud_model.h"
#include "client/ui/window_log.h"

namespace pool::ui {

void WindowInterface::draw(const WindowParts& w, const std::string& placement_problem, double now) {
  // Text grows with tall windows (1 up to 800 px high, 2 from 1600), so panes stay readable.
  int fb_width = 0, fb_height = 0;
  glfwGetFramebufferSize(w.window.get(), &fb_width, &fb_height);
  ImGui::GetIO().FontGlobalScale = hudScale(fb_height);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  const auto stage = w.session.stage();
  if (w.desk.inRoom()) {
    w.desk.setInRoom(drawEightBallRoom(w.desk.room()));
  } else if (stage == app::SessionStage::Lobby || stage == app::SessionStage::Joining) {
    drawLobbyScreen(w);
  } else {
    drawMatchHud(w, placement_problem, now);
  }
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void WindowInterface::drawLobbyScreen(const WindowParts& w) {
  const bool joining = w.session.stage() == app::SessionStage::Joining;
  if (const auto choice = drawLobby(w.session.lobby(), w.session.tournaments(), w.session.players(),
                                    joining, hotseat_, w.desk.tableOptions())) {
    w.desk.takeLobbyChoice(*choice);
  }
}

void WindowInterface::drawMatchHud(const WindowParts& w, const std::string& placement_problem,
                                   double now) {
  HudActions actions = drawHud(hudInputOf(w, placement_problem));
  // The overhead view frames the table where the panes just laid out leave it clear.
  const double margin = 2 * app::kOverheadMargin;
  w.controls.camera().setClearArea(
      clearFraction(w.table.spec.length + margin, w.table.spec.width + margin));
  w.controls.camera().setAimArea(clearColumnFraction());
  if (const client::MatchView* v = w.session.view(); v && w.controls.toggles().panes) {
    w.practice.drawPhysicsPane(*v, actions.texts);
  }
  if (json_ && actions.texts != hud_texts_) printHudLine(actions.texts);
  hud_texts_ = actions.texts;
  handleHud(w, actions, now);
}

}  // namespace pool::ui
