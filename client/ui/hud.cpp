// HUD panels.
#include "client/ui/hud.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "client/app/spoken.h"
#include "client/bot/shot_command.h"

namespace pool::ui {
namespace {

double degrees(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

void seatLine(const client::MatchView& view, int s, const std::vector<int>& local) {
  const auto& seat = view.seats[static_cast<std::size_t>(s)];
  const bool here = std::find(local.begin(), local.end(), s) != local.end();
  const bool turn = view.shooter == s;
  ImGui::Text("%s %s%s%s", turn ? ">" : " ", seat.name.empty() ? "(free)" : seat.name.c_str(),
              here ? " (you)" : "", seat.connected || seat.name.empty() ? "" : " [away]");
  ImGui::Text("    %s, %d left, %d fouls, %d racks",
              app::spoken(rules::toString(seat.group)).c_str(), seat.balls_left, seat.fouls,
              seat.racks_won);
}

// The shot clock as a bar, counted down from the state's arrival; red, with a word, near the end.
void clockBar(const client::MatchView& v) {
  if (v.shot_clock < 0.0 || v.shot_clock_total <= 0.0) return;
  static std::uint32_t seen_revision = 0;
  static double seen_at = 0.0;
  if (v.revision != seen_revision) {
    seen_revision = v.revision;
    seen_at = ImGui::GetTime();
  }
  const double left = std::max(0.0, v.shot_clock - (ImGui::GetTime() - seen_at));
  const bool warning = left <= v.settings.warningAt();
  if (warning) ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.9f, 0.2f, 0.1f, 1.0f));
  char text[32];
  std::snprintf(text, sizeof text, "%.0f s%s", std::ceil(left), warning ? ", time!" : "");
  ImGui::ProgressBar(static_cast<float>(left / v.shot_clock_total), ImVec2(220, 0), text);
  if (warning) ImGui::PopStyleColor();
}

void matchPanel(const HudInput& in, HudActions& actions) {
  ImGui::SetNextWindowPos(ImVec2(10, 10), ImGuiCond_FirstUseEver);
  ImGui::Begin("Match", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  ImGui::Text("%s%s", in.match.c_str(), in.spectating ? " (watching)" : "");
  if (!in.view) {
    ImGui::TextUnformatted("waiting for the match state...");
    ImGui::End();
    return;
  }
  const auto& v = *in.view;
  ImGui::Text("%s, rack %u, shot %u", app::spoken(client::toString(v.phase)).c_str(), v.rack,
              v.shot_number);
  ImGui::Text("%s, race to %d: %d-%d", rules::toString(v.settings.game), v.settings.race_to,
              v.seats[0].racks_won, v.seats[1].racks_won);
  for (int s = 0; s < 2; ++s) seatLine(v, s, in.local_seats);
  if (v.ball_in_hand != rules::BallInHand::None) {
    ImGui::Text("ball in hand: %s", app::spoken(rules::toString(v.ball_in_hand)).c_str());
  }
  clockBar(v);
  if (in.in_motion) ImGui::TextUnformatted("balls moving");
  if (!in.last_verdict.empty()) {
    ImGui::TextWrapped("last shot: %s", app::spokenText(in.last_verdict).c_str());
  }
  if (v.phase == client::MatchPhase::Over) {
    ImGui::Text("winner: %s (%s)",
                v.winner >= 0 ? v.seats[static_cast<std::size_t>(v.winner)].name.c_str() : "-",
                app::spoken(rules::toString(v.end)).c_str());
    const bool won =
        std::find(in.local_seats.begin(), in.local_seats.end(), v.winner) != in.local_seats.end();
    if (won && ImGui::Button("Visit the Magic Eight Ball room")) actions.visit_room = true;
    if (!in.local_seats.empty() && ImGui::Button("Rematch")) actions.rematch = true;
  }
  if (ImGui::Button("Leave to the lobby")) actions.leave = true;
  ImGui::End();
}

void choicePanel(const HudInput& in, HudActions& actions) {
  if (!in.view || in.local_shooter < 0 || in.view->options.empty()) return;
  ImGui::Begin("Your choice", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  const auto chosen = in.controls->aim().option;
  for (const rules::Choice c : in.view->options) {
    const protocol::ShotOption option = bot::optionOf(c);
    const bool on = chosen == option;
    if (ImGui::RadioButton(app::spoken(rules::toString(c)).c_str(), on)) actions.option = option;
  }
  ImGui::TextUnformatted("play on / ball in hand: then shoot; a re-rack is sent at once");
  ImGui::End();
}

void shotPanel(const HudInput& in) {
  const app::Controls& c = *in.controls;
  const app::AimState& aim = c.aim();
  const ImGuiViewport* screen = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(10, screen->WorkSize.y - 10), ImGuiCond_FirstUseEver,
                          ImVec2(0, 1));
  ImGui::Begin("Shot", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  if (in.local_shooter >= 0) {
    ImGui::Text("your turn (seat %d): aim and hold Space", in.local_shooter + 1);
  } else {
    ImGui::TextUnformatted("watching");
  }
  ImGui::Text("aim %.1f deg   elevation %.1f deg", degrees(aim.yaw), degrees(aim.elevation));
  ImGui::Text("tip side %+.2f R   height %+.2f R", aim.tip_side, aim.tip_height);
  ImGui::Text("cue speed %.2f m/s", app::cueSpeedOf(aim.power, c.limits()));
  ImGui::ProgressBar(static_cast<float>(aim.power), ImVec2(220, 0),
                     c.charging() ? "charging" : "power");
  drawTipWidget(aim.tip_side, aim.tip_height, c.limits().miscue_limit);
  if (aim.call.safety) {
    ImGui::TextUnformatted("call: safety (K to drop it)");
  } else if (aim.call.ball) {
    ImGui::Text("call: %d in the %s%s (C: next pocket)", *aim.call.ball,
                app::spoken(aim.call.pocket).c_str(),
                *aim.call.ball == rules::kEightBall ? "  <- the 8: check the pocket" : "");
  } else {
    ImGui::TextUnformatted("call: none (break)");
  }
  if (aim.cue_ball_at) {
    ImGui::Text("cue ball at (%.3f, %.3f): drag it", aim.cue_ball_at->x(), aim.cue_ball_at->y());
    if (!in.placement_problem.empty()) {
      ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "placement: %s",
                         app::spokenText(in.placement_problem).c_str());
    }
  }
  const app::Toggles& t = c.toggles();
  ImGui::Text("G aim line %s  V vectors %s  P/T/L %s%s%s", t.aim_line ? "on" : "off",
              t.vectors ? "on" : "off", t.wireframe ? "W" : "-", t.textures ? "T" : "-",
              t.lighting ? "L" : "-");
  ImGui::End();
}

void notesPanel(const HudInput& in) {
  if (!in.notes || in.notes->empty()) return;
  const ImGuiViewport* screen = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(screen->WorkSize.x - 10, 10), ImGuiCond_FirstUseEver,
                          ImVec2(1, 0));
  ImGui::Begin("Messages", nullptr, ImGuiWindowFlags_AlwaysAutoResize);
  for (const auto& n : *in.notes) {
    if (n.problem) {
      ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", app::spokenText(n.text).c_str());
    } else {
      ImGui::TextUnformatted(app::spokenText(n.text).c_str());
    }
  }
  ImGui::End();
}

}  // namespace

void drawTipWidget(double tip_side, double tip_height, double miscue_limit) {
  const float size = 90.0f, radius = size * 0.45f;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 centre(origin.x + size / 2, origin.y + size / 2);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddCircleFilled(centre, radius, IM_COL32(240, 240, 230, 255), 48);
  draw->AddCircle(centre, radius * static_cast<float>(miscue_limit), IM_COL32(200, 60, 60, 255),
                  48);
  draw->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y),
                IM_COL32(160, 160, 160, 255));
  draw->AddLine(ImVec2(centre.x, centre.y - radius), ImVec2(centre.x, centre.y + radius),
                IM_COL32(160, 160, 160, 255));
  const ImVec2 tip(centre.x + radius * static_cast<float>(tip_side),
                   centre.y - radius * static_cast<float>(tip_height));
  draw->AddCircleFilled(tip, 5.0f, IM_COL32(30, 80, 220, 255), 16);
  ImGui::Dummy(ImVec2(size, size));
}

HudActions drawHud(const HudInput& input) {
  HudActions actions;
  matchPanel(input, actions);
  choicePanel(input, actions);
  if (input.controls) shotPanel(input);
  notesPanel(input);
  return actions;
}

}  // namespace pool::ui
