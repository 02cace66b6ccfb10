// Input scripts: parsing with line-numbered errors, and frame-exact playback of presses and waits.
#include "client/app/input_script.h"

#include <gtest/gtest.h>

#include <set>

namespace pool::app::test {
namespace {

using Kind = ScriptStep::Kind;

TEST(InputScriptTest, ParsesEveryStep) {
  const auto steps = parseScript(
      "# a comment\n"
      "wait aiming\n"
      "down left ctrl shift   # trailing comment\n"
      "\n"
      "frames 3\n"
      "up LEFT\n"
      "wait shot 4\n"
      "quit\n");
  ASSERT_TRUE(steps) << steps.error();
  ASSERT_EQ(steps->size(), 6u);
  EXPECT_EQ((*steps)[0].kind, Kind::WaitAiming);
  EXPECT_EQ((*steps)[1].kind, Kind::Down);
  EXPECT_EQ((*steps)[1].key, Key::Left);
  EXPECT_TRUE((*steps)[1].mods.ctrl);
  EXPECT_TRUE((*steps)[1].mods.shift);
  EXPECT_EQ((*steps)[2].count, 3);
  EXPECT_EQ((*steps)[3].kind, Kind::Up);
  EXPECT_EQ((*steps)[4].kind, Kind::WaitShot);
  EXPECT_EQ((*steps)[4].count, 4);
  EXPECT_EQ((*steps)[5].kind, Kind::Quit);
}

TEST(InputScriptTest, ABadLineNamesItsNumber) {
  EXPECT_EQ(parseScript("frames 2\ndown F13\n").error(), "line 2: unknown key 'F13'");
  EXPECT_EQ(parseScript("down A meta\n").error(), "line 1: unknown modifier 'meta'");
  EXPECT_EQ(parseScript("mouse press 10\n").error(), "line 1: mouse press needs X Y in pixels");
  EXPECT_EQ(parseScript("mouse move nan 3\n").error(), "line 1: mouse move needs X Y in pixels");
  EXPECT_EQ(parseScript("mouse click 1 2\n").error(),
            "line 1: mouse needs 'press', 'move', 'release' or 'by'");
  EXPECT_EQ(parseScript("mouse press cue\nmouse by -2.5 3\nmouse press 4 5\n")->size(), 3u);
  EXPECT_EQ((*parseScript("mouse press cue\n"))[0].kind, ScriptStep::Kind::MouseOnCue);
  EXPECT_EQ((*parseScript("mouse by -2.5 3\n"))[0].x, -2.5);
  // A press may hold modifiers (Ctrl: a stroke); a move may not.
  const auto stroke = parseScript("mouse press 640 360 ctrl\n");
  ASSERT_TRUE(stroke) << stroke.error();
  EXPECT_TRUE((*stroke)[0].mods.ctrl);
  EXPECT_FALSE((*stroke)[0].mods.alt);
  EXPECT_EQ(parseScript("mouse press 1 2 meta\n").error(), "line 1: unknown modifier 'meta'");
  EXPECT_EQ(parseScript("mouse move 1 2 ctrl\n").error(), "line 1: mouse move takes no modifiers");
  EXPECT_EQ(parseScript("capture\n").error(), "line 1: capture needs a file");
  EXPECT_EQ((*parseScript("capture /tmp/a.png\n"))[0].path, "/tmp/a.png");
  EXPECT_EQ(parseScript("\n\nframes -1\n").error(), "line 3: frames needs a count >= 0");
  EXPECT_EQ(parseScript("jump\n").error(), "line 1: unknown step 'jump'");
  EXPECT_EQ(parseScript("wait forever\n").error(),
            "line 1: wait needs 'aiming', 'shot N', 'over', 'table', 'live' or 'rest'");
  EXPECT_FALSE(loadScript("/nonexistent/script.txt"));
}

TEST(InputScriptTest, FramesHoldAKeyForExactlyThatManyFrames) {
  ScriptPlayer player(*parseScript("down SPACE\nframes 3\nup SPACE\n"));
  const ScriptConditions any;
  auto first = player.frame(any);
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].kind, Kind::Down);
  EXPECT_TRUE(player.frame(any).empty());
  EXPECT_TRUE(player.frame(any).empty());
  auto fourth = player.frame(any);
  ASSERT_EQ(fourth.size(), 1u);
  EXPECT_EQ(fourth[0].kind, Kind::Up);
  EXPECT_TRUE(player.done());
}

TEST(InputScriptTest, WaitsHoldTheScriptUntilTheirConditionHolds) {
  ScriptPlayer player(*parseScript("wait aiming\ndown A\nwait shot 2\nquit\n"));
  EXPECT_TRUE(player.frame({false, 0}).empty());
  EXPECT_TRUE(player.frame({false, 5}).empty());
  auto pressed = player.frame({true, 0});
  ASSERT_EQ(pressed.size(), 1u);
  EXPECT_EQ(pressed[0].key, Key::A);
  EXPECT_TRUE(player.frame({true, 1}).empty());
  auto quit = player.frame({false, 2});
  ASSERT_EQ(quit.size(), 1u);
  EXPECT_EQ(quit[0].kind, Kind::Quit);
}

TEST(InputScriptTest, WaitRestAndWaitLiveHoldTheScriptWhileBallsMoveOrTheReplayShows) {
  ScriptPlayer player(*parseScript("wait rest\nwait live\nquit\n"));
  ScriptConditions moving;
  moving.moving = true;
  EXPECT_TRUE(player.frame(moving).empty());
  ScriptConditions replaying;
  replaying.replaying = true;
  EXPECT_TRUE(player.frame(replaying).empty());
  EXPECT_TRUE(player.frame(replaying).empty());
  auto quit = player.frame(ScriptConditions{});
  ASSERT_EQ(quit.size(), 1u);
  EXPECT_EQ(quit[0].kind, Kind::Quit);
}

TEST(InputScriptTest, AWaitAfterAStepIsJudgedOnTheNextFrame) {
  // Releasing Space shoots, which ends the aiming the frame's conditions still show.
  ScriptPlayer player(*parseScript("up SPACE\nwait aiming\ndown UP\n"));
  auto first = player.frame({true, 0});
  ASSERT_EQ(first.size(), 1u);
  EXPECT_EQ(first[0].kind, Kind::Up);
  EXPECT_TRUE(player.frame({false, 0}).empty());
  auto pressed = player.frame({true, 0});
  ASSERT_EQ(pressed.size(), 1u);
  EXPECT_EQ(pressed[0].key, Key::Up);
}

}  // namespace
}  // namespace pool::app::test

namespace pool::app::test {
namespace {

TEST(KeyNamesTest, EveryKeyHasOneNameAndNoNameIsEmpty) {
  std::set<Key> seen;
  for (const char* name :
       {"LEFT", "RIGHT", "UP", "DOWN",   "SPACE", "A",     "Z",     "S",  "X", "G", "V",
        "C",    "K",     "P",  "T",      "L",     "B",     "O",     "F1", "R", "N", "F11",
        "Q",    "Y",     "I",  "ESCAPE", "U",     "J",     "H",     "8",  "9", "0", "BACKSPACE",
        "F5",   "F6",    "F7", "TAB",    "MINUS", "EQUAL", "ENTER", "1",  "2", "3", "4"}) {
    const auto key = keyFromName(name);
    ASSERT_TRUE(key) << name;
    EXPECT_TRUE(seen.insert(*key).second) << name;
  }
  EXPECT_EQ(seen.size(), static_cast<std::size_t>(Key::Num4) + 1) << "a key with no name";
  EXPECT_FALSE(keyFromName(""));
  EXPECT_EQ(keyFromName("f1"), Key::F1);
}

// The number keys pick the rules' choices in the order the Your choice pane numbers them.
TEST(KeyNamesTest, NumberKeysPickTheChoices) {
  EXPECT_EQ(choiceIndexOf(Key::Num1), 0);
  EXPECT_EQ(choiceIndexOf(Key::Num2), 1);
  EXPECT_EQ(choiceIndexOf(Key::Num3), 2);
  EXPECT_EQ(choiceIndexOf(Key::Num4), 3);
  EXPECT_FALSE(choiceIndexOf(Key::Num8));
  EXPECT_FALSE(choiceIndexOf(Key::Enter));
}

}  // namespace
}  // namespace pool::app::test
