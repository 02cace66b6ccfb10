// The windowed pool-client under Xvfb against a real server over DDS: scripted keys send the
// ShotCommands the controls promise and the server accepts them; a spectating window follows a
// bot match.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <future>
#include <glm/glm.hpp>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>
#include <numbers>
#include <set>
#include <sstream>

#include "client/app/aim.h"
#include "client/app/controls.h"
#include "rules/eight_ball.h"
#include "support/client_fixture.h"
#include "support/display_check.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/window_output.h"
#include "support/xvfb_run.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;

/// This file's newer tests' DDS domains (80–89 are the concession, replay and settings tests').
constexpr Domain kWindowReplay = static_cast<Domain>(82);
constexpr Domain kWindowQuality = static_cast<Domain>(83);
constexpr Domain kWindowConcede = static_cast<Domain>(84);
constexpr Domain kWindowSpectatorReplay = static_cast<Domain>(85);
constexpr Domain kWindowStroke = static_cast<Domain>(86);
constexpr Domain kWindowNineBall = static_cast<Domain>(87);
constexpr Domain kWindowTenBall = static_cast<Domain>(88);
constexpr Domain kWindowRematch = static_cast<Domain>(89);
constexpr Domain kWindowTab = static_cast<Domain>(62);  // 63: the server's concession attacks
constexpr Domain kWindowBot = static_cast<Domain>(66);

class WindowClientTest : public ClientIntegrationTest {
 protected:
  void SetUp() override {
    ClientIntegrationTest::SetUp();
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
      POOL_NO_DISPLAY("xvfb-run is not installed");
    }
  }

  /// Starts pool-client in a window under Xvfb (in the background) with `args` and `script`.
  void startWindow(const std::vector<std::string>& args, const std::string& script) {
    std::ofstream(file("input.script")) << script;
    std::string cmd = "timeout 150 " + pool::test::xvfbRun() + " -s \"-screen 0 1280x720x24\" " +
                      std::string(POOL_BIN_DIR) + "/pool-client --domain " +
                      std::to_string(domain_) + " --json --timeout 120 --width 800 --height 450" +
                      " --script " + file("input.script");
    for (const auto& a : args) cmd += " " + a;
    cmd += " > " + file("window.out") + " 2> " + file("window.err");
    window_ = std::async(std::launch::async, [cmd] { return std::system(cmd.c_str()); });
  }

  /// Waits (up to 120 s) until the first match's break and the shot after it (the breaker's
  /// second, or the other seat's first) were sent and both verdicts came back.
  static bool firstTwoShots(MatchRecorder& recorder, std::string& match,
                            const protocol::ShotRequest*& first,
                            const protocol::ShotRequest*& second) {
    return recorder.pump(120s, [&] {
      match = recorder.firstMatch();
      const MatchView* v = recorder.latest(match);
      if (!v || v->breaker < 0) return false;
      first = recorder.nthCommand(match, v->breaker, 1);
      second = recorder.nthCommand(match, v->breaker, 2);
      if (!second) second = recorder.nthCommand(match, 1 - v->breaker, 1);
      return first && second && recorder.finals(match).size() >= 2;
    });
  }

  /// Waits until `name` sits in seat 0 of the server's first match.
  static bool seatedFirst(MatchRecorder& recorder, const std::string& name) {
    return recorder.pump(60s, [&] {
      const MatchView* v = recorder.latest(recorder.firstMatch());
      return v && v->seats[0].name == name;
    });
  }

  /// The window's exit status (waits for it).
  int windowExit() { return window_.valid() ? window_.get() : -1; }
  /// Like windowExit, but `recorder` reads all along (it follows each match as the lobby lists
  /// it, in the match's own partition, and would otherwise miss what came before it looked).
  int windowExit(MatchRecorder& recorder) {
    if (!window_.valid()) return -1;
    recorder.pump(180s, [&] { return window_.wait_for(0s) == std::future_status::ready; });
    return window_.get();
  }

  /// Runs a hotseat window with `script` (and --log-frames) to its end; returns the match once
  /// its first shot's final report arrived (empty, with a failure, if none did).
  std::string playFirstShot(MatchRecorder& recorder, const std::string& script) {
    startWindow({"--hotseat", "--play", "--log-frames"}, script);
    std::string match;
    const bool played = recorder.pump(120s, [&] {
      match = recorder.firstMatch();
      return !match.empty() && recorder.finals(match).count(1) != 0;
    });
    const int status = windowExit();
    recorder.pump(2s);
    EXPECT_TRUE(played) << "no break from the window\n" << windowErr() << logs();
    EXPECT_EQ(status, 0) << windowErr();
    return played ? match : std::string();
  }

  std::vector<nlohmann::json> windowLines(const std::string& event) const {
    return pool::test::jsonLines(file("window.out"), event);
  }

  std::string windowErr() const { return pool::test::fileText(file("window.err")); }

  std::future<int> window_;
};

TEST_F(WindowClientTest, ScriptedKeysSendTheShotCommandsTheControlsPromise) {
  open(kWindowShot, "window-shot");
  MatchRecorder recorder(kWindowShot);
  startServer({"--fast"});
  // Left for 30 frames, A for 12, Space for 45 (1/60 s of input time per scripted frame).
  startWindow({"--hotseat", "--play"},
              "wait aiming\n"
              "down LEFT\nframes 30\nup LEFT\n"
              "down A\nframes 12\nup A\n"
              "down SPACE\nframes 45\nup SPACE\n"
              // The next shot, whoever's it is: tip raised for 20 frames, the call left automatic.
              "wait aiming\n"
              "down UP ctrl\nframes 20\nup UP\n"
              "down SPACE\nframes 30\nup SPACE\n"
              "frames 30\nquit\n");
  const app::ControlRates rates;
  const protocol::CommandLimits limits;
  std::string match;
  const protocol::ShotRequest* sent = nullptr;
  const protocol::ShotRequest* second = nullptr;
  const bool seen = firstTwoShots(recorder, match, sent, second);
  const int status = windowExit();
  ASSERT_TRUE(seen) << "no accepted shot from the window\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();

  // The turns opened facing the nearest ball the shooter may hit, from the layouts the server
  // published before each shot: found here from the rules' legal first balls (WPA 3.4: on an open
  // table any ball but the 8) and the distances, not by the window's own app::turnStartYaw.
  auto stateBefore = [&](std::uint32_t shot) -> std::optional<MatchView> {
    std::optional<MatchView> found;
    for (const auto& s : recorder.states(match)) {
      if (s.shot_number == shot) found = s;
    }
    return found;
  };
  auto facing = [&](const protocol::ShotRequest& request, const MatchView& before) {
    Eigen::Vector2d cue = Eigen::Vector2d::Zero();
    for (const auto& b : before.balls) {
      if (b.id == physics::kCueBall) cue = b.pos.head<2>();
    }
    if (request.cue_ball_at) cue = *request.cue_ball_at;
    const auto legal = rules::legalFirstBalls(gameStateOf(before), before.balls);
    std::optional<double> yaw;
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& b : before.balls) {
      if (b.id == physics::kCueBall || b.id > 15 || !physics::onTable(b.state)) continue;
      if (!legal.empty() && std::find(legal.begin(), legal.end(), b.id) == legal.end()) continue;
      const Eigen::Vector2d to = b.pos.head<2>() - cue;
      if (to.norm() >= nearest) continue;
      nearest = to.norm();
      yaw = std::atan2(to.y(), to.x());
    }
    return yaw;
  };
  // The power bar fills linearly over charge_time from the slowest stroke (app::kMinCueSpeed) to
  // the server's limit (the controls' documented law), written out here.
  const auto speedAfter = [&](double held_s) {
    const double power = std::clamp(held_s / rates.charge_time, 0.0, 1.0);
    return app::kMinCueSpeed + power * (limits.max_speed - app::kMinCueSpeed);
  };
  const auto rack = stateBefore(0);
  const auto after_break = stateBefore(1);
  ASSERT_TRUE(rack && after_break);
  const auto first_yaw = facing(*sent, *rack);
  const auto second_yaw = facing(*second, *after_break);
  ASSERT_TRUE(first_yaw && second_yaw);

  // The command on the wire: each control's effect at its documented rate (a press of LEFT turns
  // one step, then the held rate past the repeat delay).
  EXPECT_NEAR(sent->cue.yaw,
              *first_yaw + rates.yaw_step + rates.yaw * (30.0 / 60.0 - rates.repeat_delay), 1e-9);
  EXPECT_NEAR(sent->cue.elevation, 12.0 / 60.0 * rates.elevation, 1e-9);
  EXPECT_NEAR(sent->cue.speed, speedAfter(45.0 / 60.0), 1e-9);
  EXPECT_FALSE(sent->cue.speed_is_ball);
  EXPECT_DOUBLE_EQ(sent->cue.tip_side, 0.0);
  EXPECT_DOUBLE_EQ(sent->cue.tip_height, 0.0);
  EXPECT_FALSE(sent->called_ball);  // the break needs no call
  ASSERT_TRUE(sent->cue_ball_at);   // the breaker has the cue ball in hand behind the head string
  EXPECT_LT(sent->cue_ball_at->x(), app::PlacementArea{}.head_string_x);

  // The next shot: the tip, the turn's opening heading, and a call the rules accept (a ball and a
  // pocket, or a safety), with the cue ball placed legally if it is in hand.
  EXPECT_NEAR(second->cue.tip_height, 20.0 / 60.0 * rates.tip, 1e-9);
  EXPECT_DOUBLE_EQ(second->cue.tip_side, 0.0);
  EXPECT_NEAR(second->cue.yaw, *second_yaw, 1e-9);
  EXPECT_NEAR(second->cue.speed, speedAfter(30.0 / 60.0), 1e-9);
  EXPECT_NE(second->safety, second->called_ball.has_value());
  EXPECT_EQ(second->called_ball.has_value(), !second->called_pocket.empty());

  // The server took both: no rejection, and both verdicts came back.
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
  EXPECT_GE(recorder.finals(match).size(), 2u);

  // The window said what it sent.
  const auto shots = windowLines("shot");
  ASSERT_EQ(shots.size(), 2u);
  EXPECT_NEAR(shots[0]["yaw"].get<double>(), sent->cue.yaw, 1e-12);
  EXPECT_NEAR(shots[1]["tip_height"].get<double>(), second->cue.tip_height, 1e-12);
}

TEST_F(WindowClientTest, AMouseStrokeBreaksAtItsSpeedAndKeysSetATouchShot) {
  open(kWindowStroke, "window-stroke");
  MatchRecorder recorder(kWindowStroke);
  startServer({"--fast"});
  // The break by a mouse stroke: Ctrl + press, 16 frames of 10 px down (the cue drawn back 16 cm
  // at the default 1 mm a pixel), then 120 px up a frame: the tip reaches the ball in the second
  // push frame (4 cm short after the first, 8 cm past after the second), so the cue's speed is
  // that frame's travel, 120 px × 1 mm in 1/60 s of script time = 7.2 m/s. Sideways wobble on the
  // way does not turn the cue. The next shot, whoever's: the speed set by keys, 13 presses of +
  // (0.95 m/s), Shift + - (0.50), five of - (0.30, the slowest), and Enter.
  std::string script = "wait aiming\nmouse press 400 225 ctrl\n";
  for (int i = 0; i < 16; ++i)
    script += "mouse by " + std::to_string(i % 2 ? 7 : -7) + " 10\nframes 1\n";
  script += "mouse by 0 -120\nframes 1\nmouse by 0 -120\nframes 1\nmouse release\n";
  script += "wait aiming\n";
  for (int i = 0; i < 13; ++i) script += "down EQUAL\nup EQUAL\n";
  script += "down MINUS shift\nup MINUS\n";
  for (int i = 0; i < 5; ++i) script += "down MINUS\nup MINUS\n";
  script += "frames 2\ndown ENTER\nup ENTER\nframes 30\nquit\n";
  startWindow({"--hotseat", "--play"}, script);

  const app::ControlRates rates;
  std::string match;
  const protocol::ShotRequest* stroke = nullptr;
  const protocol::ShotRequest* touch = nullptr;
  const bool seen = firstTwoShots(recorder, match, stroke, touch);
  const int status = windowExit();
  ASSERT_TRUE(seen) << "no two accepted shots from the window\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();

  const double stroke_speed = 120.0 * rates.stroke_scale * 60.0;  // the last push frame's travel
  EXPECT_NEAR(stroke->cue.speed, stroke_speed, 0.05 * stroke_speed);
  EXPECT_NEAR(stroke->cue.speed, stroke_speed, 1e-9) << "script time is exact";
  EXPECT_NEAR(touch->cue.speed, 0.30, 1e-9);
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
}

// 9- and 10-ball in the window: after the break the next turn opens facing the lowest-numbered
// ball on the table (WPA 9-ball and 10-ball rules: the first ball the cue ball contacts must be
// the lowest-numbered ball on the table), the shot goes that way, and the HUD names the ball on.
// In 9-ball nothing is called; in 10-ball, every shot is called: the lowest ball and a pocket,
// or a safety.
class WindowRotationTest : public WindowClientTest, public ::testing::WithParamInterface<int> {};

TEST_P(WindowRotationTest, TheTurnAfterTheBreakFacesAndCallsTheLowestBall) {
  const int game = GetParam();
  const Domain domain = game == 9 ? kWindowNineBall : kWindowTenBall;
  open(domain, "window-" + std::to_string(game) + "-ball");
  MatchRecorder recorder(domain);
  // Racks from a fixed seed: the window's break is the same stroke every run, and with a random
  // rack it sometimes drops the 9 (a win on the break: no second shot to look at).
  startServer({"--fast", "--game", std::to_string(game), "--rack-seed", "7"});
  startWindow({"--hotseat", "--play"},
              "wait aiming\ndown SPACE\nframes 45\nup SPACE\n"
              "wait aiming\nframes 10\ndown SPACE\nframes 20\nup SPACE\nframes 30\nquit\n");
  std::string match;
  const protocol::ShotRequest* brk = nullptr;
  const protocol::ShotRequest* next = nullptr;
  const bool seen = firstTwoShots(recorder, match, brk, next);
  const int status = windowExit();
  ASSERT_TRUE(seen) << "no two accepted shots from the window\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();
  EXPECT_EQ(recorder.latest(match)->settings.game,
            game == 9 ? rules::Game::NineBall : rules::Game::TenBall);

  // The layout the second shot was played from, and its lowest ball.
  std::optional<MatchView> before;
  for (const auto& st : recorder.states(match)) {
    if (st.shot_number == 1) before = st;
  }
  ASSERT_TRUE(before);
  Eigen::Vector2d cue = Eigen::Vector2d::Zero();
  int lowest = 99;
  Eigen::Vector2d lowest_at = Eigen::Vector2d::Zero();
  for (const auto& b : before->balls) {
    if (!physics::onTable(b.state)) continue;
    if (b.id == physics::kCueBall) cue = b.pos.head<2>();
    if (b.id != physics::kCueBall && b.id < lowest) {
      lowest = b.id;
      lowest_at = b.pos.head<2>();
    }
  }
  ASSERT_LT(lowest, 99);
  if (next->cue_ball_at) cue = *next->cue_ball_at;
  const Eigen::Vector2d to = lowest_at - cue;
  EXPECT_NEAR(next->cue.yaw, std::atan2(to.y(), to.x()), 1e-9) << "facing the " << lowest;
  if (game == 9) {
    EXPECT_FALSE(next->called_ball) << "9-ball calls nothing";
  } else if (!next->safety) {
    EXPECT_EQ(next->called_ball, lowest);
    EXPECT_FALSE(next->called_pocket.empty());
  }
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
  bool ball_on = false;
  for (const auto& hud : windowLines("hud")) {
    for (const auto& text : hud["texts"]) {
      ball_on = ball_on || text.get<std::string>() == "  ball on: the " + std::to_string(lowest);
    }
  }
  EXPECT_TRUE(ball_on) << "the HUD never named the " << lowest << " as the ball on";
}

INSTANTIATE_TEST_SUITE_P(Games, WindowRotationTest, ::testing::Values(9, 10),
                         [](const ::testing::TestParamInfo<int>& g) {
                           return std::to_string(g.param) + "Ball";
                         });

// Three-cushion in the window, two players at one screen: the window moves onto the carom table
// the match is played on, each player strikes their own ball (the breaker the white, then the
// other the yellow), nothing is called, and the HUD keeps the carom score.
TEST_F(WindowClientTest, HotseatThreeCushionStrikesEachPlayersOwnBallOnTheCaromTable) {
  open(kWindowThreeCushion, "window-three-cushion");
  MatchRecorder recorder(kWindowThreeCushion);
  startServer({"--fast", "--game", "three-cushion", "--rack-seed", "3"});
  startWindow({"--hotseat", "--play"},
              "wait aiming\ndown SPACE\nframes 30\nup SPACE\n"
              "wait aiming\nframes 10\ndown SPACE\nframes 30\nup SPACE\nframes 30\nquit\n");
  std::string match;
  const protocol::ShotRequest* first = nullptr;
  const protocol::ShotRequest* second = nullptr;
  const bool seen = firstTwoShots(recorder, match, first, second);
  const int status = windowExit();
  ASSERT_TRUE(seen) << "no two accepted shots from the window\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
  const auto finals = recorder.finals(match);
  ASSERT_TRUE(finals.count(1) && finals.count(2));
  const protocol::ShotReport& shot1 = finals.at(1);
  const protocol::ShotReport& shot2 = finals.at(2);
  // The server strikes the shooter's own ball: the log of each shot starts with its strike.
  const MatchView* last = recorder.latest(match);
  ASSERT_NE(last, nullptr);
  EXPECT_EQ(last->settings.game, rules::Game::ThreeCushion);
  ASSERT_FALSE(shot1.events.empty());
  EXPECT_EQ(shot1.events.front().ball_a, 0);  // the breaker's white
  const int second_striker = shot1.turn_continues ? 0 : 1;
  ASSERT_FALSE(shot2.events.empty());
  EXPECT_EQ(shot2.events.front().ball_a, second_striker);
  // Nothing called, no safety declared (three-cushion has neither).
  EXPECT_FALSE(first->called_ball);
  EXPECT_FALSE(second->called_ball);
  EXPECT_FALSE(second->safety);
  // The turn opened behind the striker's own ball, facing the nearest object ball (the rules'
  // first balls: both others), from the layout the second shot was played from.
  std::optional<MatchView> before;
  for (const auto& st : recorder.states(match)) {
    if (st.shot_number == 1) before = st;
  }
  ASSERT_TRUE(before);
  Eigen::Vector2d own = Eigen::Vector2d::Zero();
  for (const auto& b : before->balls) {
    if (b.id == second_striker) own = b.pos.head<2>();
  }
  double nearest = 1e9, facing = 0.0;
  for (const auto& b : before->balls) {
    if (b.id == second_striker) continue;
    const Eigen::Vector2d to = b.pos.head<2>() - own;
    if (to.norm() < nearest) {
      nearest = to.norm();
      facing = std::atan2(to.y(), to.x());
    }
  }
  EXPECT_NEAR(second->cue.yaw, facing, 1e-9);
  bool score = false;
  for (const auto& hud : windowLines("hud")) {
    for (const auto& text : hud["texts"]) {
      score = score || text.get<std::string>().rfind("three-cushion to 5: ", 0) == 0;
    }
  }
  EXPECT_TRUE(score) << "the HUD never gave the three-cushion score";
}

// Snooker in the window, two players at one screen (WPBSA Rules, Section 3): the window moves
// onto the snooker table; the breaker's touch from the D (the slowest stroke, 0.30 m/s) reaches
// no ball: a foul and a miss, 4 away (Section 3, 12(a) and 14); the other player is offered to
// play from here, to make the offender play again, or to have the balls put back (no free ball:
// the fifteen reds are in plain view), and key 3 puts them back: sent with no stroke, the breaker
// plays again from the D. The HUD keeps the frame score and says the ball on.
TEST_F(WindowClientTest, HotseatSnookerFoulAMissAndTheBallsPutBack) {
  open(kWindowSnooker, "window-snooker");
  MatchRecorder recorder(kWindowSnooker);
  startServer({"--fast", "--game", "snooker"});
  std::string slowest;
  for (int i = 0; i < 30; ++i) slowest += "down MINUS shift\nup MINUS\n";
  startWindow({"--hotseat", "--play"}, "wait aiming\nframes 5\n" + slowest +
                                           "down ENTER\nup ENTER\n"
                                           "wait aiming\nframes 10\ndown 3\nup 3\n"
                                           "wait aiming\nframes 20\nquit\n");
  std::string match;
  const bool answered = recorder.pump(120s, [&] {
    match = recorder.firstMatch();
    const MatchView* v = recorder.latest(match);
    return v && v->breaker >= 0 && recorder.nthCommand(match, 1 - v->breaker, 1) &&
           v->shot_number >= 1 && v->options.empty() && v->shooter == v->breaker;
  });
  const int status = windowExit(recorder);
  ASSERT_TRUE(answered) << "no foul answered from the window\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
  const MatchView last = *recorder.latest(match);
  ASSERT_EQ(last.settings.game, rules::Game::Snooker);
  const int breaker = last.breaker, other = 1 - breaker;

  // The touch from the D: a stroke with no choice; the answer: Replace, with no stroke.
  const protocol::ShotRequest* touch = recorder.nthCommand(match, breaker, 1);
  const protocol::ShotRequest* answer = recorder.nthCommand(match, other, 1);
  ASSERT_TRUE(touch && answer);
  EXPECT_EQ(touch->option, protocol::ShotOption::None);
  EXPECT_NEAR(touch->cue.speed, 0.30, 1e-9);
  ASSERT_TRUE(touch->cue_ball_at) << "in hand in the D";
  EXPECT_EQ(answer->option, protocol::ShotOption::Replace);
  EXPECT_FALSE(protocol::optionShoots(answer->option));

  // The stroke's final report (the choice's report, without a stroke, counts the same shot).
  const protocol::ShotReport* stroke = nullptr;
  for (const auto& r : recorder.reports()) {
    if (r.match == match && r.final() && r.shot_number == 1 && !r.events.empty()) stroke = &r;
  }
  ASSERT_NE(stroke, nullptr);
  const protocol::ShotReport& foul = *stroke;
  EXPECT_EQ(foul.fouls, std::vector<rules::Foul>{rules::Foul::NoBallHit});
  EXPECT_EQ(foul.options,
            (std::vector<rules::Choice>{rules::Choice::PlayOn, rules::Choice::PassBack,
                                        rules::Choice::Replace}));
  // 4 away to the other player, nothing to the breaker; the breaker in hand in the D again.
  EXPECT_EQ(last.seats[static_cast<std::size_t>(other)].points, 4);
  EXPECT_EQ(last.seats[static_cast<std::size_t>(breaker)].points, 0);
  EXPECT_EQ(last.ball_in_hand, rules::BallInHand::InTheD);
  EXPECT_EQ(last.ball_on, rules::kOnRed);

  const std::string& name = last.seats[static_cast<std::size_t>(breaker)].name;
  const std::string& other_name = last.seats[static_cast<std::size_t>(other)].name;
  const std::string score = breaker == 0 ? "0-4" : "4-0";
  bool frame_score = false, on_a_red = false, put_back = false, story = false, title = false;
  for (const auto& hud : windowLines("hud")) {
    for (const auto& t : hud["texts"]) {
      const std::string text = t.get<std::string>();
      frame_score = frame_score || text == "snooker, race to 1 frame: 0-0, this frame " + score;
      on_a_red = on_a_red || text == "  " + name + " on a red";
      title = title || text.rfind("break, frame 1, shot 0", 0) == 0;
      put_back = put_back || text == "3: Put the balls back as they were before the miss, and " +
                                         name + " plays again.";
      story = story || text.rfind("Foul and a miss by " + name +
                                      ": the cue ball hit no ball; 4 away to " + other_name + ".",
                                  0) == 0;
    }
  }
  EXPECT_TRUE(frame_score) << "the HUD never gave the frame score " << score;
  EXPECT_TRUE(on_a_red) << "the HUD never said " << name << " is on a red";
  EXPECT_TRUE(title) << "the HUD's title line never said frame 1";
  EXPECT_TRUE(put_back) << "the choice to put the balls back was never offered";
  EXPECT_TRUE(story) << "the story never told the foul and the miss";
}

// Against pool-bot --stay (the main job's bot): the player concedes the only rack of the race
// (Q, then Y), and at game over R asks for a rematch, which the bot plays: a second game starts
// at the table with both in their seats.
TEST_F(WindowClientTest, ARematchAgainstTheStayingBotStartsASecondGame) {
  open(kWindowRematch, "window-rematch");
  MatchRecorder recorder(kWindowRematch);
  startServer({"--fast"});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  })) << logs();
  const std::string match = recorder.firstMatch();
  ChildProcess& bot = startBot("alice", 41, {"--stay"});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[0].name == "alice";
  })) << logs();
  startWindow({"--play", "--match", match, "--name", "Ada"},
              "wait aiming\ndown Q\nup Q\nframes 5\ndown Y\nup Y\nwait over\nframes 30\n"
              "down R\nup R\nwait table\nframes 30\nquit\n");
  const auto secondGame = [&] {
    for (const auto& st : recorder.states(match)) {
      if (st.rack >= 2 && inPlay(st.phase) && st.seats[0].name == "alice" &&
          st.seats[1].name == "Ada") {
        return true;
      }
    }
    return false;
  };
  const bool started = recorder.pump(120s, secondGame);
  const int status = windowExit(recorder);
  ASSERT_TRUE(started) << "no second game at the table\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();
  EXPECT_TRUE(bot.running()) << "the bot left at game over: " << bot.err();
  // The first game ended by the player's concession (the race was to one rack).
  bool conceded = false;
  for (const auto& st : recorder.states(match)) {
    conceded = conceded || (st.phase == MatchPhase::Over && st.winner == 0);
  }
  EXPECT_TRUE(conceded) << "the first game did not end with the bot winning it";
}

// "Play the bot" (pool-client --bot LEVEL, the lobby's button): the window opens a fresh table, and
// once it sits there starts a pool-bot of that level for the other seat, which plays; closing the
// window stops the bot (its seat goes away from the table, and no such process is left).
TEST_F(WindowClientTest, ABotOfTheChosenLevelTakesTheOtherSeatPlaysAndGoesWithTheWindow) {
  open(kWindowBot, "window-bot");
  MatchRecorder recorder(kWindowBot);
  startServer({"--fast"});
  // If the window breaks, it plays Enter's touch shot (0.3 m/s: the cue ball stops short of the
  // rack, a foul), so the turn passes to the bot, which answers with a command whatever the rules
  // offer it; if the bot breaks, it has shot already. The window stays until it is closed below.
  startWindow({"--bot", "pro", "--name", "Ada"},
              "wait table\nwait aiming\ndown ENTER\nup ENTER\nframes 1000000\n");
  std::string match;
  int bot_seat = -1;
  const bool seated = recorder.pump(90s, [&] {
    for (const client::LobbyEntry* e : recorder.client().lobby().entries()) {
      const std::string& m = e->match;
      const MatchView* v = recorder.latest(m);
      if (!v || v->seats[0].name.empty() || v->seats[1].name.empty()) continue;
      for (int s = 0; s < 2; ++s) {
        if (v->seats[static_cast<std::size_t>(s)].name == "Pro bot" &&
            v->seats[static_cast<std::size_t>(1 - s)].name == "Ada") {
          match = m;
          bot_seat = s;
        }
      }
    }
    return bot_seat >= 0;
  });
  ASSERT_TRUE(seated) << "no table of Ada and the Pro bot\n" << windowErr() << logs();
  const bool bot_shot =
      recorder.pump(90s, [&] { return recorder.nthCommand(match, bot_seat, 1) != nullptr; });
  // The window is closed as a desktop closes it: SIGTERM to pool-client itself (the process whose
  // command starts with it, not the shell, timeout or xvfb-run around it).
  std::system(
      ("pkill -TERM -f -- '^[^ ]*/pool-client --domain " + std::to_string(kWindowBot) + " '")
          .c_str());
  const int status = windowExit(recorder);
  ASSERT_TRUE(bot_shot) << "the bot never shot\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();
  // The window stopped its bot: the seat shows it gone, and no pool-bot of this domain is left.
  EXPECT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && !v->seats[static_cast<std::size_t>(bot_seat)].connected;
  })) << "the bot stayed at the table after the window closed";
  // "[p]ool-bot": the pattern does not match the shell that runs pgrep with it.
  const std::string pattern = "[p]ool-bot --domain " + std::to_string(kWindowBot) + " ";
  EXPECT_NE(std::system(("pgrep -f -- '" + pattern + "' >/dev/null").c_str()), 0)
      << "a pool-bot outlived its window";
}

// Tab in a game: the HUD drawn is one line saying how to bring the panes back, then, Tab again,
// the panes (the Shot pane's cue speed among them) once more.
TEST_F(WindowClientTest, TabHidesTheHudInAGameAndBringsItBack) {
  open(kWindowTab, "window-tab");
  MatchRecorder recorder(kWindowTab);
  startServer({"--fast"});
  startWindow({"--hotseat", "--play"},
              "wait aiming\nframes 5\ndown TAB\nup TAB\nframes 10\ndown TAB\nup TAB\n"
              "frames 10\nquit\n");
  const int status = windowExit(recorder);
  ASSERT_EQ(status, 0) << windowErr() << logs();
  // The HUD's texts each time they changed, in order: the panes, hidden, the panes again.
  const auto shows = [](const nlohmann::json& hud, const std::string& text) {
    return std::any_of(hud["texts"].begin(), hud["texts"].end(),
                       [&](const nlohmann::json& t) { return t.get<std::string>() == text; });
  };
  const std::string speed = "cue speed 0.30 m/s (- / +)";
  int stage = 0;  // 0: before the panes, 1: panes seen, 2: hidden seen, 3: panes seen again
  for (const auto& hud : windowLines("hud")) {
    const bool panes = shows(hud, speed);
    const bool hidden = shows(hud, "Tab: show the panes");
    if (stage == 0 && panes) stage = 1;
    if (stage == 1 && hidden) {
      EXPECT_FALSE(panes) << hud.dump();
      EXPECT_EQ(hud["texts"].size(), 1u) << "only the line: " << hud.dump();
      stage = 2;
    }
    if (stage == 2 && panes) stage = 3;
  }
  EXPECT_EQ(stage, 3) << "panes, hidden, panes: not seen in that order";
}

TEST_F(WindowClientTest, ASpectatingWindowFollowsABotMatch) {
  open(kWindowSpectate, "window-spectate");
  MatchRecorder recorder(kWindowSpectate);
  startServer({"--fast"});
  startBot("alice", 5, {"--think", "0.25"});
  startBot("bob", 6, {"--think", "0.25"});
  constexpr int kShots = 3;
  startWindow({"--spectate", "any"}, "wait shot " + std::to_string(kShots) + "\nquit\n");
  const int status = windowExit(recorder);
  recorder.pump(10s, [] { return false; });
  ASSERT_EQ(status, 0) << (stalledOnLayout(recorder) ? "the bots' match stalled on a layout\n" : "")
                       << windowErr() << logs();

  const auto notes = windowLines("note");
  ASSERT_FALSE(notes.empty());
  // The first note after the drawing quality, the server's key pinned at first sight and any
  // sample the wire dropped (a live aim can come before the first state) says what is watched.
  std::size_t first = 0;
  const auto preamble = [](const std::string& text) {
    return text.find("pinned at first sight") != std::string::npos ||
           text.rfind("drawing quality: ", 0) == 0 || text.find(" dropped: ") != std::string::npos;
  };
  while (first + 1 < notes.size() && preamble(notes[first]["text"].get<std::string>())) ++first;
  EXPECT_EQ(notes[first]["text"].get<std::string>().rfind("watching ", 0), 0u);

  // Every state the window showed is one the server published, in order, up to the third shot.
  const auto states = windowLines("state");
  ASSERT_FALSE(states.empty());
  const std::string match = states[0]["match"];
  std::set<std::uint32_t> published;
  for (const auto& s : recorder.states(match)) published.insert(s.revision);
  std::uint32_t last_revision = 0, last_shot = 0;
  for (const auto& s : states) {
    EXPECT_EQ(s["match"], match);
    const auto revision = s["revision"].get<std::uint32_t>();
    EXPECT_TRUE(published.count(revision)) << revision;
    EXPECT_GE(revision, last_revision);
    last_revision = revision;
    last_shot = s["shot_number"].get<std::uint32_t>();
  }
  EXPECT_GE(last_shot, static_cast<std::uint32_t>(kShots));

  // It played the shots' motion back, and those shots were real ones.
  const auto motions = windowLines("motion");
  ASSERT_FALSE(motions.empty());
  const auto finals = recorder.finals(match);
  for (const auto& m : motions) {
    EXPECT_TRUE(finals.count(m["shot_number"].get<std::uint32_t>())) << m.dump();
  }
}

// A player whose window dies (SIGKILL) mid-match starts it again: the window finds its key and seat
// in the config folder, takes the seat back before the grace runs out, and plays on.
TEST_F(WindowClientTest, AWindowKilledMidMatchTakesItsSeatBackAndPlaysOn) {
  open(kWindowRestart, "window-restart");
  MatchRecorder recorder(kWindowRestart);
  startServer({"--grace", "60"});
  // The first window sits down and waits (it never shoots); then a bot takes the other seat.
  startWindow({"--play", "--name", "Wendy"}, "frames 100000\n");
  ASSERT_TRUE(seatedFirst(recorder, "Wendy")) << windowErr() << logs();
  const std::string match = recorder.firstMatch();
  ChildProcess& bot = startBot("bert", 5);
  ASSERT_TRUE(recorder.pump(30s,
                            [&] {
                              const MatchView* v = recorder.latest(match);
                              return v && v->phase == MatchPhase::Break && v->shooter == 0;
                            }))
      << "the rack did not start with Wendy to break\n"
      << logs();
  // The window writes it when it reads the server's reply, which may be after the bot sat down.
  const std::string kept = file("config") + "/pool/players/Wendy.seat";
  ASSERT_TRUE(recorder.pump(10s, [&] { return std::ifstream(kept).good(); }))
      << "the window kept no seat file";

  // Killed: the server shows her away once her lease runs out.
  const std::string window = "^" + std::string(POOL_BIN_DIR) + "/pool-client --domain " +
                             std::to_string(domain_) + " ";  // the program, not xvfb-run
  ASSERT_EQ(std::system(("pkill -KILL -f '" + window + "'").c_str()), 0);
  windowExit();
  ASSERT_TRUE(recorder.pump(30s,
                            [&] {
                              const MatchView* v = recorder.latest(match);
                              return v && !v->seats[0].connected;
                            }))
      << "the server never showed the killed window away\n"
      << logs();

  // Started again with the same config folder: the seat comes back and the break is played.
  startWindow({"--play", "--name", "Wendy"},
              "wait aiming\ndown SPACE\nframes 40\nup SPACE\nframes 30\nquit\n");
  const bool back = recorder.pump(60s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[0].connected;
  });
  const bool played = back && recorder.pump(60s, [&] {
    return recorder.finals(match).size() >= 1 && recorder.nthCommand(match, 0, 1) != nullptr;
  });
  const int status = windowExit();
  ASSERT_TRUE(back) << "the restarted window did not take its seat back\n" << windowErr() << logs();
  ASSERT_TRUE(played) << "the restarted window did not break\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();
  bool said = false;
  for (const auto& note : windowLines("note")) {
    said = said || note.value("text", "").find("took back seat 1 in " + match) != std::string::npos;
  }
  EXPECT_TRUE(said) << "the window did not say it took its seat back";
  EXPECT_TRUE(recorder.rejections().empty()) << recorder.rejections().front().reject_text;
  EXPECT_EQ(recorder.latest(match)->seats[0].name, "Wendy");
  bot.kill(SIGTERM);
}

/// True when `text`, with the players' `names` taken out, has no underscore.
bool freeOfIdentifiers(std::string text, const std::vector<std::string>& names) {
  for (const auto& name : names) {
    for (auto at = text.find(name); !name.empty() && at != std::string::npos;
         at = text.find(name)) {
      text.erase(at, name.size());
    }
  }
  return text.find('_') == std::string::npos;
}

// A game ends (the opponent's window dies and the grace runs out): the game-over screen names the
// winner and why, says the departed opponent cannot have a rematch, and N gets a new game at a
// free table. No text the HUD drew on the way holds an identifier.
TEST_F(WindowClientTest, TheGameOverScreenStartsASecondGameAtAFreeTable) {
  open(kWindowNewGame, "window-new-game");
  MatchRecorder recorder(kWindowNewGame);
  startServer({"--grace", "2"});
  startWindow({"--play", "--name", "Wendy"},
              "wait over\nframes 20\ndown R\nup R\nframes 20\ndown N\nup N\n"
              "wait table\nframes 30\nquit\n");
  ASSERT_TRUE(seatedFirst(recorder, "Wendy")) << windowErr() << logs();
  const std::string first = recorder.firstMatch();
  ChildProcess& bot = startBot("bert_the_bot", 5);
  ASSERT_TRUE(recorder.pump(30s, [&] {
    const MatchView* v = recorder.latest(first);
    return v && v->seats[1].name == "bert_the_bot" && v->phase == MatchPhase::Break;
  })) << logs();
  bot.kill(SIGKILL);
  ASSERT_TRUE(recorder.pump(90s,
                            [&] {
                              const MatchView* v = recorder.latest(first);
                              return v && v->phase == MatchPhase::Over;
                            }))
      << "the match was not forfeited to Wendy\n"
      << logs();
  EXPECT_EQ(recorder.latest(first)->winner, 0);

  // The window started a second game: Wendy holds a seat at another table, not over.
  std::string second;
  const bool seated = recorder.pump(60s, [&] {
    for (const auto* e : recorder.client().lobby().entries()) {
      const MatchView* v = recorder.latest(e->match);
      if (e->match != first && v && v->phase != MatchPhase::Over &&
          (v->seats[0].name == "Wendy" || v->seats[1].name == "Wendy")) {
        second = e->match;
        return true;
      }
    }
    return false;
  });
  const int status = windowExit();
  ASSERT_TRUE(seated) << "Wendy got no table after the game over\n" << windowErr() << logs();
  EXPECT_EQ(status, 0) << windowErr();

  // What the HUD said on the way.
  bool winner_said = false, departed_said = false, new_game_offered = false;
  const auto huds = windowLines("hud");
  ASSERT_FALSE(huds.empty());
  for (const auto& hud : huds) {
    for (const auto& t : hud["texts"]) {
      const std::string text = t.get<std::string>();
      EXPECT_TRUE(freeOfIdentifiers(text, {"bert_the_bot"})) << text;
      winner_said = winner_said || text.find("Wendy (you) wins: a forfeit") != std::string::npos;
      departed_said =
          departed_said || text.find("bert_the_bot has left the table") != std::string::npos;
      new_game_offered = new_game_offered || text == "New game (N)";
    }
  }
  EXPECT_TRUE(winner_said);
  std::string over_screen;
  for (const auto& hud : huds) {
    const std::string dump = hud["texts"].dump();
    if (dump.find("wins") != std::string::npos) over_screen = dump;
  }
  EXPECT_TRUE(departed_said) << over_screen;
  EXPECT_TRUE(new_game_offered) << over_screen;
  bool refused_rematch = false;
  for (const auto& note : windowLines("note")) {
    refused_rematch = refused_rematch ||
                      note.value("text", "").find("bert_the_bot has left the table: no rematch") !=
                          std::string::npos;
  }
  EXPECT_TRUE(refused_rematch) << "R against a departed opponent said nothing\n"
                               << std::ifstream(file("window.out")).rdbuf();
}

/// A logged frame's pixel for table point `p` through its view and projection (column-major).
Eigen::Vector2d pixelOf(const nlohmann::json& drawn, const Eigen::Vector3d& p) {
  Eigen::Matrix4d view, projection;
  for (int c = 0; c < 4; ++c) {
    for (int r = 0; r < 4; ++r) {
      view(r, c) = drawn["view"][static_cast<std::size_t>(4 * c + r)].get<double>();
      projection(r, c) = drawn["projection"][static_cast<std::size_t>(4 * c + r)].get<double>();
    }
  }
  const Eigen::Vector4d clip = projection * view * Eigen::Vector4d(p.x(), p.y(), p.z(), 1.0);
  const double w = drawn["width"].get<double>(), h = drawn["height"].get<double>();
  return {(clip.x() / clip.w() * 0.5 + 0.5) * w, (0.5 - clip.y() / clip.w() * 0.5) * h};
}

Eigen::Vector3d cueIn(const TableFrame& frame) {
  for (const auto& b : frame.balls) {
    if (b.id == physics::kCueBall) return b.pos;
  }
  return Eigen::Vector3d::Constant(std::nan(""));
}

/// The cue ball's path through a shot's frames as the server sent them.
struct ServerPath {
  explicit ServerPath(std::vector<TableFrame> shot) : frames(std::move(shot)) {
    // Snapshots are 1/60 s apart: where the cue ball is struck or strikes a ball its path turns a
    // corner that interpolation between two snapshots cuts; those times are kept to skip.
    turns.push_back(0.0);
    for (std::size_t i = 2; i < frames.size(); ++i) {
      const double dt1 = frames[i - 1].sim_time - frames[i - 2].sim_time;
      const double dt2 = frames[i].sim_time - frames[i - 1].sim_time;
      const Eigen::Vector3d v1 = (cueIn(frames[i - 1]) - cueIn(frames[i - 2])) / dt1;
      const Eigen::Vector3d v2 = (cueIn(frames[i]) - cueIn(frames[i - 1])) / dt2;
      if ((v2 - v1).norm() > 0.2) turns.push_back(frames[i - 1].sim_time);
    }
  }

  /// Where the server says the cue ball is at `t` s after the strike.
  Eigen::Vector3d at(double t) const {
    if (t <= frames.front().sim_time) return cueIn(frames.front());
    for (std::size_t i = 1; i < frames.size(); ++i) {
      if (frames[i].sim_time < t) continue;
      const double u = (t - frames[i - 1].sim_time) / (frames[i].sim_time - frames[i - 1].sim_time);
      return Eigen::Vector3d(cueIn(frames[i - 1]) + u * (cueIn(frames[i]) - cueIn(frames[i - 1])));
    }
    return cueIn(frames.back());
  }

  /// True within 50 ms of a corner of the path.
  bool nearTurn(double t) const {
    return std::any_of(turns.begin(), turns.end(),
                       [&](double c) { return std::abs(t - c) < 0.05; });
  }

  std::vector<TableFrame> frames;
  std::vector<double> turns;
};

/// Where the ray through pixel `px` of `camera` meets the horizontal plane at height `z` (table
/// frame, m): the inverse of the camera's own projection.
glm::vec3 onPlane(const ReportedCamera& camera, const Eigen::Vector2d& px, float z) {
  const glm::mat4 inverse = glm::inverse(camera.projection * camera.view);
  const float nx = static_cast<float>(px.x() / camera.width * 2.0 - 1.0);
  const float ny = static_cast<float>(1.0 - px.y() / camera.height * 2.0);
  const glm::vec4 a = inverse * glm::vec4(nx, ny, -1.0f, 1.0f);
  const glm::vec4 b = inverse * glm::vec4(nx, ny, 1.0f, 1.0f);
  const glm::vec3 near = glm::vec3(a) / a.w, far = glm::vec3(b) / b.w;
  return near + (far - near) * ((z - near.z) / (far.z - near.z));
}

// The breaker drags the cue ball in hand across the kitchen: in two frames captured while dragging
// the ball is drawn under the cursor, and no longer where the other had it. Then the break: in
// every frame drawn, the cue ball is where the server's frames put it at the time played back
// (within 2 px), from the release on.
TEST_F(WindowClientTest, TheCueBallInHandFollowsTheCursorAndThenTheServersFrames) {
  open(kWindowBallInHand, "window-ball-in-hand");
  MatchRecorder recorder(kWindowBallInHand);
  startServer({});  // frames paced at 60 Hz, as a player sees them
  std::string script = "wait aiming\nframes 60\nmouse press cue\nframes 2\n";
  // Each move: to the right and a little back, px (over open felt: the Match and Shot panes are
  // on the left, and the aiming view draws the cue ball low in the column between them and the
  // log, near the window's bottom edge).
  const Eigen::Vector2d step(3.5, 1.0);
  const std::array<int, 2> captured_after{10, 30};
  for (int i = 1; i <= 30; ++i) {
    script += "mouse by 3.5 1\n";
    if (i == captured_after[0] || i == captured_after[1]) {
      script += "capture " + file("drag-" + std::to_string(i) + ".png") + "\n";
    }
    script += "frames 1\n";
  }
  script +=
      "mouse release\nframes 10\ndown SPACE\nframes 10\nup SPACE\nwait shot 1\n"
      "frames 30\nquit\n";
  const std::string match = playFirstShot(recorder, script);
  ASSERT_FALSE(match.empty());
  const auto drawn = windowLines("drawn");
  ASSERT_FALSE(drawn.empty());

  // The drag, in the captured pixels. The cursor is where the test's script moved it: the press
  // (on the ball, before any move) plus `step` a move. The captured frame's camera, as the window
  // reports it (not mirrored), gives the ball's size there: the cursor's ray meets the plane of
  // the ball's centre (z = R) at P, and R seen at P is r px. A ball drawn within 0.4 r of the
  // cursor covers the disc of 0.6 r round it; more than half of that disc shows the cue ball's
  // white (as lit anywhere on the table: a light neutral grey), the rest its shading. Where the
  // other capture had the cursor (20 moves, 73 px, away: beyond the ball's radius and the disc's,
  // asserted) the ball is gone: under a tenth of the disc is white there (the aim line may cross
  // it).
  std::optional<Eigen::Vector2d> press;
  for (const auto& d : drawn) {
    if (d["dragging"].get<bool>()) {
      press = Eigen::Vector2d(d["mouse"][0].get<double>(), d["mouse"][1].get<double>());
      break;
    }
  }
  ASSERT_TRUE(press) << "no frame drawn dragging";
  const auto spec = table::loadTableSpec("wpa-9ft");
  ASSERT_TRUE(spec) << spec.error();
  const auto radius = static_cast<float>(spec->params.ball_radius);
  std::array<Eigen::Vector2d, 2> cursor;
  std::array<double, 2> disc{};
  std::array<Image, 2> image;
  for (std::size_t k = 0; k < 2; ++k) {
    const std::string png = file("drag-" + std::to_string(captured_after[k]) + ".png");
    const auto line = std::find_if(drawn.begin(), drawn.end(), [&](const nlohmann::json& d) {
      return d.value("capture", "") == png;
    });
    ASSERT_NE(line, drawn.end()) << "no frame drawn for " << png;
    ASSERT_TRUE((*line)["dragging"].get<bool>());
    ReportedCamera camera;
    camera.width = (*line)["width"];
    camera.height = (*line)["height"];
    camera.view = matrixOf((*line)["view"]);
    camera.projection = matrixOf((*line)["projection"]);
    ASSERT_EQ(camera.mirrored(), "");
    image[k] = loadPng(png);
    ASSERT_EQ(image[k].width, camera.width) << png;
    ASSERT_EQ(image[k].height, camera.height) << png;
    cursor[k] = *press + captured_after[k] * step;
    const Eigen::Vector2d mouse((*line)["mouse"][0].get<double>(),
                                (*line)["mouse"][1].get<double>());
    ASSERT_LT((mouse - cursor[k]).norm(), 1e-6) << "the script's cursor went elsewhere";
    const glm::vec3 at = onPlane(camera, cursor[k], radius);
    const glm::vec3 centre = camera.pixel(at);
    ASSERT_LT(glm::length(glm::vec2(centre) - glm::vec2(cursor[k].x(), cursor[k].y())), 0.5f);
    const double r =
        glm::length(glm::vec2(camera.pixel(at + radius * camera.up())) - glm::vec2(centre));
    ASSERT_GT(r, 3.0) << "the ball too small to judge";
    disc[k] = 0.6 * r;
  }
  const auto white = [&](std::size_t k, std::size_t at) {
    const double area = std::numbers::pi * disc[at] * disc[at];
    return countInDisc(image[k], cursor[at].x(), cursor[at].y(), disc[at],
                       [](const Rgb& p) { return ballColourInAnyLight(physics::kCueBall, p); }) /
           area;
  };
  ASSERT_GT((cursor[1] - cursor[0]).norm(), (1.0 + 0.6) * std::max(disc[0], disc[1]) / 0.6 + 2.0);
  EXPECT_GT(white(0, 0), 0.5) << "after 10 moves: the ball under the cursor";
  EXPECT_GT(white(1, 1), 0.5) << "after 30 moves: the ball under the cursor";
  EXPECT_LT(white(1, 0), 0.1) << "after 30 moves: the ball gone from where it was";
  EXPECT_LT(white(0, 1), 0.1) << "after 10 moves: the ball not yet where it will be";

  // The break (a soft one: it runs long enough to see) as drawn against the server's frames.
  const ServerPath path(recorder.frames(match, 1));
  const auto& frames = path.frames;
  ASSERT_GE(frames.size(), 10u);
  const protocol::ShotRequest* sent =
      recorder.nthCommand(match, recorder.latest(match)->breaker, 1);
  ASSERT_TRUE(sent && sent->cue_ball_at);
  // From the first frame after the release (the last one dragging, then the first not aiming).
  std::size_t from = 0;
  for (std::size_t i = 0; i < drawn.size(); ++i) {
    if (drawn[i]["dragging"].get<bool>()) from = i;
  }
  while (from < drawn.size() && drawn[from]["aiming"].get<bool>()) ++from;
  int compared = 0, before_motion = 0;
  for (std::size_t i = from; i < drawn.size(); ++i) {
    const auto& d = drawn[i];
    if (d["aiming"].get<bool>()) break;  // the next turn
    if (!d.contains("cue_px")) continue;
    const Eigen::Vector2d px(d["cue_px"][0].get<double>(), d["cue_px"][1].get<double>());
    const bool this_shot = !d["shot"].is_null() && d["shot"].get<std::uint32_t>() == 1;
    if (this_shot && d["moving"].get<bool>()) {
      const double t = d["play_time"].get<double>();
      if (path.nearTurn(t)) continue;
      EXPECT_LT((px - pixelOf(d, path.at(t))).norm(), 2.0) << "t " << t << " " << d.dump();
      ++compared;
    } else if (!this_shot && compared == 0) {
      // Sent, its frames not here yet: the ball stays where it was put.
      const Eigen::Vector3d put(sent->cue_ball_at->x(), sent->cue_ball_at->y(),
                                cueIn(frames.front()).z());
      EXPECT_LT((px - pixelOf(d, put)).norm(), 2.0) << d.dump();
      ++before_motion;
    }
  }
  EXPECT_GE(compared, 20) << "too few frames of the break drawn";
  EXPECT_GE(before_motion, 1);
  EXPECT_LT((*sent->cue_ball_at - cueIn(frames.front()).head<2>()).norm(), 1e-6);
}

// After the break, I replays it: the drawn cue ball passes again through the server's frames of
// that shot (within 2 px, projected through the camera each frame reports), from the strike on,
// while the view is turned (right drag) during the replay; then the live table is back. A second
// window then replays the stored break from the lobby (--replay) to the server's layout at rest.
TEST_F(WindowClientTest, TheInstantReplayDrawsTheLastShotsFramesAgain) {
  open(kWindowReplay, "window-replay");
  MatchRecorder recorder(kWindowReplay);
  startServer({});
  std::string script =
      "wait aiming\ndown SPACE\nframes 10\nup SPACE\nwait shot 1\nframes 120\n"
      "down I\nframes 1\nup I\nframes 20\n";
  // The view orbits while the replay runs (a right drag is not scripted: Shift + arrows are the
  // aiming player's orbit).
  script += "down RIGHT shift\nframes 20\nup RIGHT\nwait live\nframes 10\nquit\n";
  const std::string match = playFirstShot(recorder, script);
  ASSERT_FALSE(match.empty());
  const ServerPath path(recorder.frames(match, 1));
  ASSERT_GE(path.frames.size(), 10u);

  int compared = 0;
  double first_time = 1e9, last_time = -1.0;
  std::set<std::string> views;
  bool live_after = false;
  for (const auto& d : windowLines("drawn")) {
    if (!d.value("replaying", false)) {
      live_after = live_after || compared > 0;
      continue;
    }
    ASSERT_FALSE(live_after) << "one replay, not two";
    const double t = d["replay_time"].get<double>();
    first_time = std::min(first_time, t);
    last_time = std::max(last_time, t);
    views.insert(d["view"].dump());
    if (!d.contains("cue_px")) continue;  // behind the eye
    if (path.nearTurn(t)) continue;
    const Eigen::Vector2d px(d["cue_px"][0].get<double>(), d["cue_px"][1].get<double>());
    EXPECT_LT((px - pixelOf(d, path.at(t))).norm(), 2.0) << "t " << t << " " << d.dump();
    ++compared;
  }
  EXPECT_GE(compared, 20) << "too few replayed frames\n" << windowErr();
  EXPECT_LT(first_time, 0.1) << "the replay starts at the strike";
  EXPECT_GT(last_time, 0.3) << "the replay ran on";
  EXPECT_GT((path.at(last_time) - path.at(first_time)).norm(), 0.05)
      << "the replayed cue ball moved as it did in the break";
  EXPECT_GT(views.size(), 5u) << "the view moved during the replay";
  EXPECT_TRUE(live_after) << "the live table came back after the replay";

  // The same shot as the server stored it, replayed from the lobby (pool-client --replay): the
  // pane names it, and it comes to rest with every ball where the server's state after it has
  // it (a pocketed ball off the table).
  const MatchView* rest = recorder.latest(match);
  ASSERT_NE(rest, nullptr);
  ASSERT_EQ(rest->shot_number, 1u);
  startWindow({"--replay", match, "--shot", "1", "--log-frames", "--fresh-identity"},
              "wait rest\nframes 5\nquit\n");
  EXPECT_EQ(windowExit(recorder), 0) << windowErr();
  nlohmann::json stored;
  bool played = false;
  for (const auto& d : windowLines("drawn")) {
    if (!d.contains("stored")) continue;
    stored = d["stored"];
    played = played || (stored["time"].get<double>() > 0.1 && !stored["at_rest"].get<bool>());
  }
  ASSERT_FALSE(stored.is_null()) << "no stored shot drawn\n" << windowErr();
  EXPECT_TRUE(played) << "the stored shot was not seen in motion";
  EXPECT_EQ(stored["match"], match);
  EXPECT_EQ(stored["shot"], 1);
  EXPECT_TRUE(stored["at_rest"].get<bool>());
  std::map<int, nlohmann::json> drawn;
  for (const auto& b : stored["balls"]) drawn[b["id"].get<int>()] = b;
  EXPECT_EQ(drawn.size(), rest->balls.size());
  for (const auto& b : rest->balls) {
    ASSERT_TRUE(drawn.count(b.id)) << "ball " << b.id;
    EXPECT_EQ(drawn[b.id]["on"].get<bool>(), physics::onTable(b.state)) << "ball " << b.id;
    if (!physics::onTable(b.state)) continue;
    EXPECT_NEAR(drawn[b.id]["x"].get<double>(), b.pos.x(), 1e-6) << "ball " << b.id;
    EXPECT_NEAR(drawn[b.id]["y"].get<double>(), b.pos.y(), 1e-6) << "ball " << b.id;
  }
  bool named = false;
  for (const auto& h : windowLines("hud")) {
    for (const auto& text : h["texts"]) {
      named =
          named || text.get<std::string>().rfind("Replay of " + match + ", shot 1 of 1: ", 0) == 0;
    }
  }
  EXPECT_TRUE(named) << "the pane did not name the shot";
}

// The drawing quality chosen in the settings file is the one the window draws with, whatever
// the renderer (under Xvfb, auto alone would pick light).
TEST_F(WindowClientTest, TheWindowDrawsWithTheQualityKeptInTheSettings) {
  open(kWindowQuality, "window-quality");
  for (const std::string quality : {"high", "full", "light"}) {
    SCOPED_TRACE(quality);
    const std::string dir = file("config") + "/pool";
    std::filesystem::create_directories(dir);
    std::ofstream(dir + "/settings.conf") << "volume = 0.5\nquality = " << quality << "\n";
    startWindow({"--log-frames"}, "frames 5\nquit\n");
    EXPECT_EQ(windowExit(), 0) << windowErr();
    const auto drawn = windowLines("drawn");
    ASSERT_FALSE(drawn.empty()) << windowErr();
    for (const auto& d : drawn) EXPECT_EQ(d.value("quality", ""), quality) << d.dump();
    bool said = false;
    for (const auto& note : windowLines("note")) {
      said = said || note.value("text", "") == "drawing quality: " + quality + " (" + quality + ")";
    }
    EXPECT_TRUE(said);
  }
}

// A player concedes from the window: Q asks (naming the opponent), Y concedes; the server gives
// the rack, here the whole race to 1, to the bot, and the window says so with names.
TEST_F(WindowClientTest, QThenYConcedesTheRackToTheOpponent) {
  open(kWindowConcede, "window-concede");
  MatchRecorder recorder(kWindowConcede);
  startServer({});
  startWindow({"--play", "--name", "Wendy"},
              "wait aiming\nframes 5\ndown Q\nup Q\nframes 5\ndown Y\nup Y\nwait over\n"
              "frames 20\nquit\n");
  ASSERT_TRUE(seatedFirst(recorder, "Wendy")) << windowErr() << logs();
  const std::string match = recorder.firstMatch();
  startBot("bert", 5, {"--think", "30"});
  ASSERT_TRUE(recorder.pump(90s,
                            [&] {
                              const MatchView* v = recorder.latest(match);
                              return v && v->phase == MatchPhase::Over;
                            }))
      << windowErr() << logs();
  EXPECT_EQ(windowExit(), 0) << windowErr();
  const MatchView over = *recorder.latest(match);
  EXPECT_EQ(over.winner, 1);
  EXPECT_EQ(over.shot_number, 0u) << "conceded before any shot";
  EXPECT_EQ(over.last_verdict, "seat 0 conceded the rack: seat 1 won the match");
  bool asked = false, told = false;
  for (const auto& hud : windowLines("hud")) {
    for (const auto& t : hud["texts"]) {
      const std::string text = t.get<std::string>();
      asked = asked || text.rfind("Wendy, concede this rack to bert?", 0) == 0;
      told = told || text == "Wendy conceded the rack: bert won the match";
    }
  }
  EXPECT_TRUE(asked) << "the question names the opponent";
  EXPECT_TRUE(told) << "the banner says who conceded, by name";
}

// A spectator replays the last shot while the bots think, and the next shot's frames end the
// replay: no frame is drawn replaying while a shot moves.
TEST_F(WindowClientTest, ASpectatorsReplayGivesWayToTheNextShot) {
  open(kWindowSpectatorReplay, "window-spectator-replay");
  MatchRecorder recorder(kWindowSpectatorReplay);
  startServer({});
  startBot("alice", 5, {"--think", "3"});
  startBot("bob", 6, {"--think", "3"});
  startWindow({"--spectate", "any", "--log-frames"},
              "wait shot 1\nwait rest\ndown I\nframes 1\nup I\nwait shot 2\nwait rest\nquit\n");
  const int status = windowExit();
  ASSERT_EQ(status, 0) << windowErr() << logs();
  int replayed = 0, moving_after = 0;
  for (const auto& d : windowLines("drawn")) {
    if (d.value("replaying", false)) {
      ++replayed;
      EXPECT_FALSE(d["moving"].get<bool>()) << "a replay drawn over a live shot: " << d.dump();
    } else if (replayed > 0 && d["moving"].get<bool>()) {
      ++moving_after;
    }
  }
  EXPECT_GE(replayed, 5) << windowErr();
  EXPECT_GE(moving_after, 5) << "the next shot was drawn live";
}
}  // namespace
}  // namespace pool::client::test
