// Every HUD pane lies inside the window at every size from 1024×600 to 2560×1440: the HUD drawn by
// Dear ImGui (no window needed: its layout is the same without a renderer) with every pane open at
// once, long texts included, and each pane's rectangle checked against the screen. Tab hides every
// pane but a question asked; the help pane is opaque.
#include <imgui.h>
#include <imgui_internal.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <deque>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "client/app/controls.h"
#include "client/ui/hud.h"

namespace pool::ui::test {
namespace {

/// A Dear ImGui context with its font atlas built: the HUD's layout without drawing it.
class ImGuiFrames {
 public:
  ImGuiFrames() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int w = 0, h = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &w, &h);
    ImGui::StyleColorsDark();
  }
  ~ImGuiFrames() { ImGui::DestroyContext(); }
  ImGuiFrames(const ImGuiFrames&) = delete;
  ImGuiFrames& operator=(const ImGuiFrames&) = delete;

  /// Lays the HUD out for a `width` × `height` window (a few frames, as auto-sized panes settle)
  /// and returns each pane shown: its name and rectangle (x0, y0, x1, y1).
  std::vector<std::pair<std::string, ImRect>> panes(const HudInput& in, int width, int height) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.FontGlobalScale = hudScale(height);
    io.DeltaTime = 1.0f / 60.0f;
    for (int frame = 0; frame < 4; ++frame) {
      ImGui::NewFrame();
      (void)drawHud(in);
      ImGui::Render();
    }
    std::vector<std::pair<std::string, ImRect>> out;
    backgrounds_.clear();
    for (ImGuiWindow* w : ImGui::GetCurrentContext()->Windows) {
      if (!w->WasActive || w->Hidden || (w->Flags & ImGuiWindowFlags_ChildWindow) != 0) continue;
      if (std::string(w->Name).rfind("Debug##", 0) == 0) continue;  // ImGui's own, never shown
      out.emplace_back(w->Name, w->Rect());
      // A pane's draw list starts with its background (the first vertex's colour), unless it has
      // none.
      if ((w->Flags & ImGuiWindowFlags_NoBackground) == 0 && !w->DrawList->VtxBuffer.empty()) {
        backgrounds_[w->Name] = (w->DrawList->VtxBuffer[0].col >> IM_COL32_A_SHIFT) & 0xFF;
      }
    }
    return out;
  }

  /// The alpha (0–255) of each pane's background as last laid out by panes().
  const std::map<std::string, unsigned>& backgrounds() const { return backgrounds_; }

 private:
  std::map<std::string, unsigned> backgrounds_;
};

/// A player aiming mid-race with every pane up: the match, the last shot's banner, a choice of
/// the rules, the shot, the match log, the concession question and the help with the settings.
struct Table {
  client::MatchView view;
  app::Controls controls{protocol::CommandLimits{}, app::PlacementArea{},
                         app::CameraRig(2.54, 1.27, 16.0 / 9.0)};
  std::deque<app::SessionNote> notes;
  std::deque<std::string> log;

  Table() {
    view.match = "srv-12";
    view.phase = client::MatchPhase::Open;
    view.shooter = 0;
    view.shot_number = 41;
    view.rack = 3;
    view.seats[0].name = "Alexandrina Featherstonehaugh";
    view.seats[1].name = "Bartholomew Cholmondeley";
    view.seats[0].connected = view.seats[1].connected = true;
    view.seats[0].balls_left = view.seats[1].balls_left = 7;
    view.options = {rules::Choice::PlayOn, rules::Choice::OpponentReBreaks};
    view.shot_clock = 25.0;
    view.shot_clock_total = 30.0;
    view.settings.shot_clock = 30.0;
    const std::string story =
        "Foul: Bartholomew Cholmondeley's cue ball went into the foot left corner after hitting "
        "the 5 first. Alexandrina Featherstonehaugh has the cue ball in hand anywhere on the "
        "table.";
    for (int i = 0; i < 60; ++i) {
      log.push_back(std::to_string(i + 1) + ". " + story);
      notes.push_back({"shot " + std::to_string(i) + " of seat 1 accepted", i % 7 == 0});
    }
    controls.startTurn(Eigen::Vector3d(-0.6, 0.1, 0.028575), rules::BallInHand::None);
  }

  HudInput input() const {
    HudInput in;
    in.view = &view;
    in.match = view.match;
    in.local_seats = {0};
    in.local_shooter = 0;
    in.controls = &controls;
    in.last_verdict = "seat 1 fouled";
    in.notes = &notes;
    in.banner = log.back();
    in.log = &log;
    in.help = true;
    in.settings_note = "kept in /home/someone/.config/pool/settings.conf";
    in.can_concede = true;
    in.concede_asked = true;
    return in;
  }
};

void expectInside(ImGuiFrames& imgui, const HudInput& in, std::size_t at_least) {
  for (const auto& [w, h] : {std::pair{1024, 600}, std::pair{1280, 720}, std::pair{1366, 768},
                             std::pair{1920, 1080}, std::pair{2560, 1440}}) {
    const auto panes = imgui.panes(in, w, h);
    EXPECT_GE(panes.size(), at_least) << w << "x" << h;
    for (const auto& [name, r] : panes) {
      SCOPED_TRACE(name + " at " + std::to_string(w) + "x" + std::to_string(h));
      EXPECT_GE(r.Min.x, 0.0f);
      EXPECT_GE(r.Min.y, 0.0f);
      EXPECT_LE(r.Max.x, static_cast<float>(w));
      EXPECT_LE(r.Max.y, static_cast<float>(h));
      EXPECT_GT(r.GetWidth(), 0.0f);
      EXPECT_GT(r.GetHeight(), 0.0f);
    }
  }
}

TEST(HudPanes, EveryPaneOfARackInPlayStaysInsideTheWindow) {
  ImGuiFrames imgui;
  const Table table;
  // Match, last shot, choice, shot, match log, concession question, keys.
  expectInside(imgui, table.input(), 7);
}

TEST(HudPanes, EveryPaneOfTheGameOverScreenStaysInsideTheWindow) {
  ImGuiFrames imgui;
  Table table;
  table.view.phase = client::MatchPhase::Over;
  table.view.winner = 1;
  table.view.end = rules::GameEnd::Forfeit;
  table.view.options.clear();
  HudInput in = table.input();
  in.local_shooter = -1;
  in.can_concede = in.concede_asked = false;
  // Match, last shot, shot, match log, game over, keys.
  expectInside(imgui, in, 6);
}

std::vector<std::string> names(const std::vector<std::pair<std::string, ImRect>>& panes) {
  std::vector<std::string> out;
  for (const auto& [name, r] : panes) out.push_back(name);
  return out;
}

TEST(HudPanes, TabHidesEveryPaneButTheQuestionAskedAndBringsThemBack) {
  ImGuiFrames imgui;
  Table table;
  // The Tab key toggles what the HUD is given.
  table.controls.keyDown(app::Key::Tab, {});
  HudInput in = table.input();
  in.panes = table.controls.toggles().panes;
  ASSERT_FALSE(in.panes);
  using ::testing::UnorderedElementsAre;
  EXPECT_THAT(names(imgui.panes(in, 1280, 720)),
              UnorderedElementsAre("HUD hidden", "Concede the rack?"));
  in.concede_asked = false;
  EXPECT_THAT(names(imgui.panes(in, 1280, 720)), UnorderedElementsAre("HUD hidden"));
  table.controls.keyDown(app::Key::Tab, {});
  in.panes = table.controls.toggles().panes;
  EXPECT_TRUE(in.panes);
  EXPECT_GE(imgui.panes(in, 1280, 720).size(), 6u) << "the panes are back";
}

TEST(HudPanes, TheHelpPaneIsOpaqueOverTheOthers) {
  ImGuiFrames imgui;
  const Table table;
  (void)imgui.panes(table.input(), 1280, 720);
  const auto& bg = imgui.backgrounds();
  ASSERT_TRUE(bg.count("Keys (F1 closes)"));
  EXPECT_EQ(bg.at("Keys (F1 closes)"), 255u);
  // The other panes keep the style's translucent background, so this check can tell them apart.
  ASSERT_TRUE(bg.count("Match"));
  EXPECT_LT(bg.at("Match"), 255u);
}

}  // namespace
}  // namespace pool::ui::test
