// A stored shot exported as a pool-sim scenario file: its name says the match and the shot; the
// file holds the layout at the strike and the cue as played, and pool-sim's parser reads them back.
#include "client/ui/shot_export.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>

#include "scenario/scenario.h"

namespace pool::ui {
namespace {

constexpr double kExportR = 0.028575;

physics::Ball exportBallAt(int id, double x, double y) {
  physics::Ball b;
  b.id = id;
  b.pos = physics::Vec3(x, y, kExportR);
  return b;
}

/// Shot 3 of srv-1: the cue ball, the 1 and the 5 on the table, the 2 pocketed before it.
protocol::HistoryShot storedShot() {
  protocol::HistoryShot s;
  s.match = "srv-1";
  s.found = true;
  s.shot_number = 3;
  s.shots = 9;
  s.table = "wpa-9ft";
  physics::Ball pocketed = exportBallAt(2, 1.27, 0.635);
  pocketed.state = physics::MotionState::Pocketed;
  s.before = {exportBallAt(0, -0.61, 0.123), exportBallAt(1, 0.5, 0.05), pocketed,
              exportBallAt(5, 0.9, -0.31)};
  s.cue.yaw = 0.3;
  s.cue.tip_side = 0.25;
  s.cue.tip_height = -0.4;
  s.cue.elevation = 0.1;
  s.cue.speed = 3.2;
  s.after = s.before;
  return s;
}

/// A fresh folder of this test's own.
std::filesystem::path freshDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("pool-shot-export-" + std::to_string(::getpid()) + "-" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

TEST(ShotExport, TheFileIsNamedByTheMatchAndTheShotInAnyFolderItIsWrittenTo) {
  EXPECT_EQ(scenarioFileName("srv-1", 3), "srv-1-shot-3.json");
  EXPECT_EQ(scenarioFileName("a1b2_c-17", 120), "a1b2_c-17-shot-120.json");
  // A match id is the server's: it never names another folder.
  EXPECT_EQ(scenarioFileName("../x/y z", 2), "___x_y_z-shot-2.json");
}

TEST(ShotExport, TheFileHoldsTheLayoutAtTheStrikeAndTheCueAsPlayed) {
  const auto dir = freshDir("layout");
  const auto written = exportShot(storedShot(), dir);
  ASSERT_TRUE(written) << written.error();
  EXPECT_TRUE(written->is_absolute());
  EXPECT_EQ(*written, std::filesystem::absolute(dir / "srv-1-shot-3.json").lexically_normal());
  std::ifstream in(*written);
  std::stringstream text;
  text << in.rdbuf();
  const auto json = nlohmann::json::parse(text.str());
  EXPECT_EQ(json["table"], "wpa-9ft");
  // The balls on the table at the strike, the pocketed 2 left out.
  ASSERT_EQ(json["balls"].size(), 3u);
  const double expected[3][3] = {{0, -0.61, 0.123}, {1, 0.5, 0.05}, {5, 0.9, -0.31}};
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(json["balls"][i]["id"].get<int>(), static_cast<int>(expected[i][0]));
    EXPECT_EQ(json["balls"][i]["x"].get<double>(), expected[i][1]);
    EXPECT_EQ(json["balls"][i]["y"].get<double>(), expected[i][2]);
  }
  const auto& shot = json["shot"];
  EXPECT_NEAR(shot["yaw_deg"].get<double>(), 0.3 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_NEAR(shot["elevation_deg"].get<double>(), 0.1 * 180.0 / std::numbers::pi, 1e-9);
  EXPECT_EQ(shot["tip_side"].get<double>(), 0.25);
  EXPECT_EQ(shot["tip_height"].get<double>(), -0.4);
  EXPECT_EQ(shot["speed"].get<double>(), 3.2);
  EXPECT_EQ(shot["speed_is"], "cue");

  // pool-sim's own parser reads the very shot back.
  const auto loaded = scenario::loadScenario(written->string());
  ASSERT_TRUE(loaded) << loaded.error();
  EXPECT_EQ(loaded->shot.yaw, 0.3);
  EXPECT_EQ(loaded->shot.elevation, 0.1);
  EXPECT_EQ(loaded->shot.speed, 3.2);
  ASSERT_EQ(loaded->balls.size(), 3u);
  EXPECT_EQ(loaded->balls[0].pos.x(), -0.61);
  EXPECT_EQ(loaded->balls[2].id, 5);
  std::filesystem::remove_all(dir);
}

TEST(ShotExport, RefusedInOneLineWhenThereIsNoStrokeOrNoFolder) {
  protocol::HistoryShot rerack = storedShot();
  rerack.shoots = false;
  const auto no_stroke = exportShot(rerack, freshDir("rerack"));
  ASSERT_FALSE(no_stroke);
  EXPECT_EQ(no_stroke.error(), "shot 3 re-racked the table: no stroke to export");

  protocol::HistoryShot carom = storedShot();
  carom.cue.ball = 1;
  const auto other_ball = exportShot(carom, freshDir("carom"));
  ASSERT_FALSE(other_ball);
  EXPECT_EQ(other_ball.error(), "shot 3 struck ball 1: a scenario file strikes the cue ball only");

  const auto no_dir = exportShot(storedShot(), "/nonexistent-pool-folder/deeper");
  ASSERT_FALSE(no_dir);
  EXPECT_EQ(no_dir.error(), "cannot write /nonexistent-pool-folder/deeper/srv-1-shot-3.json");
  EXPECT_EQ(no_dir.error().find('\n'), std::string::npos);
}

}  // namespace
}  // namespace pool::ui
