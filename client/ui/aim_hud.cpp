// The aim scene's HUD: Dear ImGui laid out and drawn offscreen.
#include "client/ui/aim_hud.h"

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <imgui_internal.h>

#include "client/ui/hud.h"
#include "client/ui/pane_rects.h"

namespace pool::ui {

AimHud::AimHud(int width, int height, const app::Controls& controls)
    : width_(width), height_(height), controls_(controls) {
  // A player's turn mid-rack, as the window shows it: both seats, the last shot's story in the
  // banner and the match log, the Shot pane with the aim.
  view_.match = "srv-1";
  view_.phase = client::MatchPhase::Open;
  view_.shooter = 0;
  view_.breaker = 1;
  view_.shot_number = 6;
  view_.rack = 1;
  view_.seats[0].name = "Ada";
  view_.seats[1].name = "Bob";
  view_.seats[0].connected = view_.seats[1].connected = true;
  view_.seats[0].balls_left = view_.seats[1].balls_left = 7;
  for (const char* story :
       {"Bob broke and pocketed nothing. Ada to shoot.", "Ada pocketed nothing. Bob to shoot.",
        "Bob played a safety. Ada to shoot."}) {
    log_.emplace_back(story);
  }
  notes_.push_back({"seat 1 in srv-1", false});
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;
  io.ConfigWindowsMoveFromTitleBarOnly = true;
  ImGui::StyleColorsDark();
  unsigned char* pixels = nullptr;
  int w = 0, h = 0;
  io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
  // Auto-sized panes settle over a few frames, as in the window.
  for (int i = 0; i < 4; ++i) {
    prepare();
    ImGui::NewFrame();
    frame();
    ImGui::Render();
  }
  standing_ = standingPaneRects();
}

AimHud::~AimHud() {
  if (gl_) ImGui_ImplOpenGL3_Shutdown();
  ImGui::DestroyContext();
}

void AimHud::prepare() const {
  ImGuiIO& io = ImGui::GetIO();
  io.DisplaySize = ImVec2(static_cast<float>(width_), static_cast<float>(height_));
  io.FontGlobalScale = hudScale(height_);
  io.DeltaTime = 1.0f / 60.0f;
}

void AimHud::frame() {
  HudInput in;
  in.view = &view_;
  in.match = view_.match;
  in.local_seats = {0};
  in.local_shooter = 0;
  in.controls = &controls_;
  in.notes = &notes_;
  in.banner = log_.back();
  in.log = &log_;
  in.can_concede = true;
  (void)drawHud(in);
}

void AimHud::draw(bool last) {
  if (!gl_) {
    ImGui_ImplOpenGL3_Init("#version 330 core");
    gl_ = true;
  }
  ImGui_ImplOpenGL3_NewFrame();
  prepare();
  ImGui::NewFrame();
  frame();
  ImGui::Render();
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  panes_ = nlohmann::json::array();
  for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
    if (!w->Active || w->Hidden || (w->Flags & ImGuiWindowFlags_ChildWindow) != 0) continue;
    if (std::string(w->Name).rfind("Debug##", 0) == 0) continue;
    const ImRect r = w->Rect();
    panes_.push_back({{"name", w->Name}, {"rect", {r.Min.x, r.Min.y, r.Max.x, r.Max.y}}});
  }
  if (last) {
    ImGui_ImplOpenGL3_Shutdown();
    gl_ = false;
  }
}

nlohmann::json AimHud::panesJson() const {
  return panes_;
}

}  // namespace pool::ui
