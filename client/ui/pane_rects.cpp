// The HUD's standing panes' rectangles from Dear ImGui's windows.
#include "client/ui/pane_rects.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <string_view>

namespace pool::ui {

std::vector<app::ScreenRect> standingPaneRects() {
  std::vector<app::ScreenRect> out;
  ImGuiContext* context = ImGui::GetCurrentContext();
  if (context == nullptr) return out;
  for (ImGuiWindow* w : context->Windows) {
    if (!w->Active || w->Hidden || (w->Flags & ImGuiWindowFlags_ChildWindow) != 0) continue;
    const std::string_view name = w->Name;
    if (name != "Match" && name != "Last shot" && name != "Shot" && name != "Match log") continue;
    const ImRect r = w->Rect();
    out.push_back({r.Min.x, r.Min.y, r.Max.x, r.Max.y});
  }
  return out;
}

namespace {

/// `px` as fractions of the window.
app::ScreenRect fractionOf(const app::ScreenRect& px, const ImVec2& size) {
  return {px.x0 / size.x, px.y0 / size.y, px.x1 / size.x, px.y1 / size.y};
}

}  // namespace

app::ScreenRect clearFraction(double length, double breadth) {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  if (!(size.x > 0.0f && size.y > 0.0f)) return {0.0, 0.0, 1.0, 1.0};
  return fractionOf(app::clearRectFor(size.x, size.y, standingPaneRects(), length, breadth), size);
}

app::ScreenRect clearColumnFraction() {
  const ImVec2 size = ImGui::GetIO().DisplaySize;
  if (!(size.x > 0.0f && size.y > 0.0f)) return {0.0, 0.0, 1.0, 1.0};
  return fractionOf(app::clearColumnFor(size.x, size.y, standingPaneRects()), size);
}

}  // namespace pool::ui
