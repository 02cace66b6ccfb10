// The window's interface: an ImGui frame with the room, the lobby or the HUD, and its choices.
#include "client/ui/window_interface.h"

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "client/ui/pane_rects.h"
#include "client/ui/replay_pane.h"
#include "client/ui/shot_export.h"
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
  const auto stage = w.session.stage();
  const bool lobby = stage == app::SessionStage::Lobby || stage == app::SessionStage::Joining;
  if (script_mouse_ && lobby) {
    // After the backend read the real mouse, before the frame takes it in.
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = ImVec2(static_cast<float>(script_mouse_->at.x()),
                         static_cast<float>(script_mouse_->at.y()));
    io.MouseDown[0] = script_mouse_->down;
  }
  ImGui::NewFrame();
  if (w.desk.inRoom()) {
    w.desk.setInRoom(drawEightBallRoom(w.desk.room()));
  } else if (stage == app::SessionStage::Lobby && w.session.stored().isOpen()) {
    drawStoredReplay(w, now);
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
                                    joining, hotseat_, w.desk.tableOptions(), w.session.playerKey(),
                                    w.session.recent().gone())) {
    w.desk.takeLobbyChoice(*choice);
  }
}

void WindowInterface::drawStoredReplay(const WindowParts& w, double now) {
  app::StoredReplay& stored = w.session.stored();
  const ReplayPaneLines lines = replayPaneLines(stored, export_line_);
  if (json_ && lines.all() != hud_texts_) printHudLine(lines.all());
  hud_texts_ = lines.all();
  const auto action = drawReplayPane(stored, lines);
  if (!action) return;
  switch (*action) {
    case ReplayAction::Previous:
      stored.previous();
      export_line_.clear();
      break;
    case ReplayAction::Next:
      stored.next();
      export_line_.clear();
      break;
    case ReplayAction::Again:
      stored.again(now);
      break;
    case ReplayAction::Export:
      if (const protocol::HistoryShot* shot = stored.shown()) {
        // Into the working directory, as a practice table's F5 saves.
        const auto written = exportShot(*shot, ".");
        export_line_ = written ? "exported to " + written->string() + " (pool-sim " +
                                     written->filename().string() + ")"
                               : "export: " + written.error();
        w.notes.add({export_line_, !written});
      }
      break;
    case ReplayAction::Back:
      w.session.closeStored();
      export_line_.clear();
      break;
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
