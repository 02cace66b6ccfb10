// Settings survive a save and a load; a bad file is refused whole, with its line, and left alone.
#include "client/app/settings.h"

#include <gtest/gtest.h>

#include <fstream>
#include <random>

namespace pool::app::test {
namespace {

class SettingsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("pool-settings-" + std::to_string(std::random_device{}()));
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }
  std::filesystem::path file() const { return dir_ / "pool" / "settings.conf"; }
  void write(const std::string& text) {
    std::filesystem::create_directories(file().parent_path());
    std::ofstream(file()) << text;
  }
  std::filesystem::path dir_;
};

TEST_F(SettingsTest, NoFileGivesTheDefaults) {
  const auto s = loadSettings(file());
  ASSERT_TRUE(s) << s.error();
  EXPECT_EQ(*s, Settings{});
}

TEST_F(SettingsTest, WhatIsSavedIsLoadedBack) {
  Settings s;
  s.full_screen = true;
  s.volume = 0.35;
  s.aim_line = false;
  s.vectors = true;
  s.quality = "light";
  s.stroke_mm = 2.5;
  s.follow_cue = true;
  s.pane_places["log"] = {0.25, 0.5};
  s.pane_places["match"] = {0.5, 0.125};
  ASSERT_TRUE(saveSettings(file(), s));
  const auto back = loadSettings(file());
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(*back, s);
  EXPECT_FALSE(std::filesystem::exists(file().string() + ".tmp"));
}

TEST_F(SettingsTest, EachQualityIsKeptAsChosen) {
  for (const char* quality : {"auto", "high", "full", "light"}) {
    Settings s;
    s.quality = quality;
    ASSERT_TRUE(saveSettings(file(), s));
    const auto back = loadSettings(file());
    ASSERT_TRUE(back) << back.error();
    EXPECT_EQ(back->quality, quality);
  }
  write("quality = full\n");
  const auto written = loadSettings(file());
  ASSERT_TRUE(written) << written.error();
  EXPECT_EQ(written->quality, "full");
  EXPECT_EQ(Settings{}.quality, "auto") << "a file without the key leaves the choice to the window";
}

TEST_F(SettingsTest, ABadLineIsRefusedWithItsNumberAndTheFileKept) {
  const std::string text = "# mine\nvolume = 0.5\n\naim_line = maybe\n";
  write(text);
  const auto s = loadSettings(file());
  ASSERT_FALSE(s);
  EXPECT_EQ(s.error(), file().string() + " line 4: bad value 'maybe' for aim_line");
  for (const char* bad :
       {"volume = 1.5\n", "volume = nan\n", "volume = 0.5 loud\n", "colour = red\n",
        "full_screen\n", "quality = ultra\n", "quality = \n", "stroke_mm = 0\n",
        "stroke_mm = 5.5\n", "stroke_mm = inf\n", "pane_match = 0.5\n", "pane_menu = 0.1, 0.1\n",
        "pane_shot = 1.5, 0\n", "pane_log = 0.2, 0.3, 0.4\n"}) {
    write(bad);
    EXPECT_FALSE(loadSettings(file())) << bad;
  }
  write(text);
  (void)loadSettings(file());
  std::ifstream in(file());
  const std::string kept((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_EQ(kept, text);
}

}  // namespace
}  // namespace pool::app::test
