// Every HUD pane lies inside the window at every size from 1024×600 to 2560×1440: the HUD drawn by
// Dear ImGui (no window needed: its layout is the same without a renderer) with every pane open at
// once, long texts included, and each pane's rectangle checked against the screen. Tab hides every
// pane but a question asked; the help pane is opaque; panes move and their places are kept; the
// Shot pane says the shot that runs; the overhead view keeps the table clear of the panes.
#include <imgui.h>
#include <imgui_internal.h>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "client/app/clear_area.h"
#include "client/app/controls.h"
#include "client/ui/hud.h"
#include "table/table_spec.h"

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

  /// One frame of a `width` × `height` window with the mouse at `mouse`, its left button `down`:
  /// what the HUD asked for.
  HudActions frame(const HudInput& in, int width, int height, ImVec2 mouse, bool down) {
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(static_cast<float>(width), static_cast<float>(height));
    io.FontGlobalScale = hudScale(height);
    io.DeltaTime = 1.0f / 60.0f;
    io.ConfigWindowsMoveFromTitleBarOnly = true;  // as the window sets it
    io.MousePos = mouse;
    io.MouseDown[ImGuiMouseButton_Left] = down;
    ImGui::NewFrame();
    HudActions actions = drawHud(in);
    ImGui::Render();
    return actions;
  }

  /// The rectangle of pane `name` as last laid out.
  static ImRect rectOf(const char* name) {
    ImGuiWindow* w = ImGui::FindWindowByName(name);
    return w ? w->Rect() : ImRect();
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

// While the shot this screen sent runs, the Shot pane says that shot in numbers, not the aim the
// controls reset for the next turn ("aim 0.00, 0.30 m/s" before).
TEST(HudPanes, WhileOurShotRunsTheShotPaneSaysThatShot) {
  ImGuiFrames imgui;
  Table table;
  table.view.options.clear();
  table.controls.stopAiming();  // the shot was sent: the controls are back to watching
  HudInput in = table.input();
  in.help = false;
  in.concede_asked = false;
  in.local_shooter = -1;
  in.in_motion = true;
  protocol::ShotRequest shot;
  shot.cue.yaw = 0.5;  // 28.65 degrees
  shot.cue.elevation = 0.1;
  shot.cue.speed = 3.25;
  shot.cue.tip_height = -0.3;
  in.last_shot = shot;
  HudActions said;
  for (int frame = 0; frame < 2; ++frame) said = imgui.frame(in, 1280, 720, ImVec2(-1, -1), false);
  const auto has = [&](const std::string& text) {
    return std::find(said.texts.begin(), said.texts.end(), text) != said.texts.end();
  };
  EXPECT_TRUE(has("your shot: aim 28.65 deg, cue elevation 5.7 deg, cue speed 3.25 m/s"))
      << ::testing::PrintToString(said.texts);
  EXPECT_TRUE(has("tip side +0.00 R   height -0.30 R")) << ::testing::PrintToString(said.texts);
  for (const auto& text : said.texts) {
    EXPECT_EQ(text.rfind("cue speed 0.30", 0), std::string::npos) << "the reset aim: " << text;
  }
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

namespace pool::ui::test {
namespace {

// A standing pane dragged by its title stays where it is let go, and that place goes out with the
// settings (fractions of the window); given back, it is drawn there again; a pane not moved
// stays at its anchor.
TEST(HudPanes, APaneDraggedByItsTitleStaysWhereItIsLetGoAndThePlaceIsKept) {
  Table table;
  table.view.options.clear();
  HudInput in = table.input();
  in.help = false;
  in.concede_asked = false;
  ImRect match, shot;
  std::optional<HudActions> let_go;
  {
    ImGuiFrames imgui;
    (void)imgui.panes(in, 1280, 720);
    match = ImGuiFrames::rectOf("Match");
    shot = ImGuiFrames::rectOf("Shot");
    ASSERT_GT(match.GetWidth(), 100.0f);
    const ImVec2 grab(match.Min.x + 60.0f, match.Min.y + 6.0f);  // on its title bar
    (void)imgui.frame(in, 1280, 720, grab, false);
    EXPECT_FALSE(imgui.frame(in, 1280, 720, grab, true).settings);
    for (int i = 1; i <= 10; ++i) {
      const float step = static_cast<float>(i);
      const HudActions during =
          imgui.frame(in, 1280, 720, ImVec2(grab.x + 40.0f * step, grab.y + 20.0f * step), true);
      EXPECT_FALSE(during.settings) << "nothing kept while dragging";
    }
    let_go = imgui.frame(in, 1280, 720, ImVec2(grab.x + 400.0f, grab.y + 200.0f), false);
  }
  ASSERT_TRUE(let_go->settings) << "the place goes out when the drag ends";
  const auto& places = let_go->settings->pane_places;
  ASSERT_EQ(places.count("match"), 1u);
  EXPECT_EQ(places.size(), 1u) << "only the pane moved";
  EXPECT_NEAR(places.at("match")[0] * 1280.0, match.Min.x + 400.0, 1.0);
  EXPECT_NEAR(places.at("match")[1] * 720.0, match.Min.y + 200.0, 1.0);

  // Kept (a later run's settings, a fresh HUD): drawn there, the Shot pane still at its anchor.
  ImGuiFrames fresh;
  in.settings = *let_go->settings;
  (void)fresh.panes(in, 1280, 720);
  EXPECT_NEAR(ImGuiFrames::rectOf("Match").Min.x, match.Min.x + 400.0f, 1.0f);
  EXPECT_NEAR(ImGuiFrames::rectOf("Match").Min.y, match.Min.y + 200.0f, 1.0f);
  EXPECT_NEAR(ImGuiFrames::rectOf("Shot").Min.x, shot.Min.x, 1.0f);
  EXPECT_NEAR(ImGuiFrames::rectOf("Shot").Min.y, shot.Min.y, 1.0f);
}

/// The bounding box in pixels of the playing surface (z = 0 to a ball's height) of a `length` ×
/// `breadth` table seen from `v` in a `width` × `height` window: the test's own projection
/// (glm's lookAt with +z up and perspective, as a camera draws), not the renderer's.
app::ScreenRect surfaceOnScreen(const app::ViewPoint& v, int width, int height, double length,
                                double breadth) {
  const auto g = [](const Eigen::Vector3d& p) {
    return glm::vec3(static_cast<float>(p.x()), static_cast<float>(p.y()),
                     static_cast<float>(p.z()));
  };
  const glm::mat4 view = glm::lookAt(g(v.eye), g(v.target), glm::vec3(0, 0, 1));
  const glm::mat4 projection =
      glm::perspective(glm::radians(static_cast<float>(v.fov_y_deg)),
                       static_cast<float>(width) / static_cast<float>(height), 0.05f, 50.0f);
  app::ScreenRect box{1e9, 1e9, -1e9, -1e9};
  for (double x : {-length / 2, length / 2}) {
    for (double y : {-breadth / 2, breadth / 2}) {
      for (double z : {0.0, 0.05715}) {
        const glm::vec4 c = projection * view * glm::vec4(glm::vec3(g({x, y, z})), 1.0f);
        const double px = (c.x / c.w * 0.5 + 0.5) * width;
        const double py = (0.5 - c.y / c.w * 0.5) * height;
        box = {std::min(box.x0, px), std::min(box.y0, py), std::max(box.x1, px),
               std::max(box.y1, py)};
      }
    }
  }
  return box;
}

// The overhead view (O) at its whole-table zoom: on every table and at 1280×720 and larger, the
// playing surface lies inside the window and under none of the panes that stay up in play (the
// match, the last shot's banner with a long story, the shot, a long match log), and it is drawn
// large: its shorter side on screen at least a third of the window's height.
TEST(HudPanes, TheOverheadViewShowsThePlayingSurfaceClearOfThePanes) {
  ImGuiFrames imgui;
  Table table;
  table.view.options.clear();
  HudInput in = table.input();
  in.help = false;
  in.concede_asked = false;
  for (const char* name : {"wpa-7ft", "wpa-8ft", "wpa-9ft"}) {
    const auto spec = table::loadTableSpec(name);
    ASSERT_TRUE(spec) << spec.error();
    const double length = spec->length, breadth = spec->width;
    for (const auto& [w, h] : {std::pair{1280, 720}, std::pair{1366, 768}, std::pair{1920, 1080},
                               std::pair{2560, 1440}}) {
      SCOPED_TRACE(std::string(name) + " at " + std::to_string(w) + "x" + std::to_string(h));
      std::vector<app::ScreenRect> standing;
      for (const auto& [pane, r] : imgui.panes(in, w, h)) {
        if (pane == "Match" || pane == "Last shot" || pane == "Shot" || pane == "Match log") {
          standing.push_back({r.Min.x, r.Min.y, r.Max.x, r.Max.y});
        }
      }
      ASSERT_EQ(standing.size(), 4u);
      // As the window does each frame: the clear area from the panes laid out, then O.
      const app::ScreenRect px = app::clearRectFor(
          w, h, standing, length + 2 * app::kOverheadMargin, breadth + 2 * app::kOverheadMargin);
      app::CameraRig rig(length, breadth, static_cast<double>(w) / h);
      rig.setClearArea({px.x0 / w, px.y0 / h, px.x1 / w, px.y1 / h});
      rig.setOverhead(true);
      rig.settle();
      const app::ScreenRect surface = surfaceOnScreen(rig.view(), w, h, length, breadth);
      EXPECT_GE(surface.x0, 0.0);
      EXPECT_GE(surface.y0, 0.0);
      EXPECT_LE(surface.x1, w);
      EXPECT_LE(surface.y1, h);
      for (const auto& pane : standing) {
        EXPECT_FALSE(surface.overlaps(pane))
            << "surface " << surface.x0 << "," << surface.y0 << "-" << surface.x1 << ","
            << surface.y1 << " under a pane at " << pane.x0 << "," << pane.y0 << "-" << pane.x1
            << "," << pane.y1;
      }
      EXPECT_GE(std::min(surface.width(), surface.height()), h / 3.0);
    }
  }
}

}  // namespace
}  // namespace pool::ui::test
