// validateShotCommand: representable bad values are caught with their reason; good ones pass.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <limits>
#include <numbers>

#include "net/convert.h"
#include "net/shot_command_check.h"
#include "net/wire_fields.h"

namespace pool::net {
namespace {

using namespace protocol;

/// A legal, ordinary command.
Sample<pool_ShotCommand> goodCommand() {
  ShotRequest r;
  r.match = "srv-1";
  r.seat = 0;
  r.seq = 1;
  r.cue = {0.3, 0.1, 0.2, 0.1, 3.0, false};
  return toWire(r);
}

struct Case {
  const char* name;
  std::function<void(pool_ShotCommand&)> spoil;
  CommandProblem expected;
};

TEST(ShotCommandCheck, GoodCommandPasses) {
  const auto c = goodCommand();
  const CommandCheck check = validateShotCommand(*c);
  EXPECT_TRUE(check.ok()) << check.error();
  EXPECT_TRUE(check.error().empty());
}

TEST(ShotCommandCheck, EachSpoiledFieldIsCaughtWithItsReason) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const Case cases[] = {
      {"empty match", [](auto& c) { setText(c.match, ""); }, CommandProblem::BadMatchId},
      {"unterminated match", [](auto& c) { std::memset(c.match, 'a', sizeof c.match); },
       CommandProblem::BadMatchId},
      {"seat 2", [](auto& c) { c.seat = 2; }, CommandProblem::BadSeat},
      {"seat -1", [](auto& c) { c.seat = -1; }, CommandProblem::BadSeat},
      {"nan yaw", [=](auto& c) { c.yaw = nan; }, CommandProblem::NonFinite},
      {"inf speed", [=](auto& c) { c.speed = inf; }, CommandProblem::NonFinite},
      {"nan tip", [=](auto& c) { c.tip_height = nan; }, CommandProblem::NonFinite},
      {"nan placement unused", [=](auto& c) { c.cue_ball_y = nan; }, CommandProblem::NonFinite},
      {"option 17", [](auto& c) { setRawValue(c.option, 17); }, CommandProblem::BadOption},
      {"option -1", [](auto& c) { setRawValue(c.option, -1); }, CommandProblem::BadOption},
      {"speed 0", [](auto& c) { c.speed = 0.0; }, CommandProblem::SpeedOutOfRange},
      {"speed 12.01", [](auto& c) { c.speed = 12.01; }, CommandProblem::SpeedOutOfRange},
      {"elevation -0.01", [](auto& c) { c.elevation = -0.01; },
       CommandProblem::ElevationOutOfRange},
      {"elevation 90 deg", [](auto& c) { c.elevation = std::numbers::pi / 2; },
       CommandProblem::ElevationOutOfRange},
      {"miscue", [](auto& c) { c.tip_side = 0.4, c.tip_height = 0.31; },
       CommandProblem::TipOutOfRange},
      {"yaw 7", [](auto& c) { c.yaw = 7.0; }, CommandProblem::YawOutOfRange},
      {"called ball 22", [](auto& c) { c.called_ball = 22, setText(c.called_pocket, "left_side"); },
       CommandProblem::BadCall},
      {"called ball 0", [](auto& c) { c.called_ball = 0, setText(c.called_pocket, "left_side"); },
       CommandProblem::BadCall},
      {"pocket without ball", [](auto& c) { setText(c.called_pocket, "left_side"); },
       CommandProblem::BadCall},
      {"pocket with a space", [](auto& c) { c.called_ball = 3, setText(c.called_pocket, "a b"); },
       CommandProblem::BadCall},
      {"placement off the table",
       [](auto& c) { c.has_cue_ball_placement = true, c.cue_ball_x = 1.3; },
       CommandProblem::PlacementOutOfRange},
      {"signature 65 bytes", [](auto& c) { resizeSequence(c.signature, 65); },
       CommandProblem::BadSignature},
  };
  for (const Case& k : cases) {
    auto c = goodCommand();
    k.spoil(*c);
    const CommandCheck check = validateShotCommand(*c);
    EXPECT_EQ(check.code(), k.expected)
        << k.name << ": got " << toString(check.code()) << " (" << check.error() << ")";
    EXPECT_FALSE(check.error().empty()) << k.name;
  }
}

TEST(ShotCommandCheck, EdgesOfRangesAreLegal) {
  auto c = goodCommand();
  c->speed = 12.0;
  c->elevation = 89.0 * std::numbers::pi / 180;
  c->tip_side = 0.0, c->tip_height = -0.5;  // exactly the miscue limit
  c->yaw = -2 * std::numbers::pi;
  c->has_cue_ball_placement = true, c->cue_ball_x = -1.27, c->cue_ball_y = 0.635;
  c->called_ball = 15, setText(c->called_pocket, "foot_right_corner");
  resizeSequence(c->signature, 64);
  const CommandCheck check = validateShotCommand(*c);
  EXPECT_TRUE(check.ok()) << check.error();
}

TEST(ShotCommandCheck, ABallWithoutAPocketIsSnookersNomination) {
  auto c = goodCommand();
  c->called_ball = 21;  // the black, nominated (the rules of a pool game refuse it)
  const CommandCheck check = validateShotCommand(*c);
  EXPECT_TRUE(check.ok()) << check.error();
}

TEST(ShotCommandCheck, ChoicesWithoutAShotSkipTheCueRanges) {
  auto c = goodCommand();
  c->option = pool_OPTION_REBREAK;
  c->speed = 0.0;  // no shot: the cue values are unused
  EXPECT_TRUE(validateShotCommand(*c).ok());
  c->speed = std::numeric_limits<double>::quiet_NaN();  // but still must be finite
  EXPECT_EQ(validateShotCommand(*c).code(), CommandProblem::NonFinite);
}

// Snooker's options are known on the wire: a free ball carries its stroke; the balls put back
// carry none (the window sends a harmless placeholder, as for a re-rack). Past them, unknown.
TEST(ShotCommandCheck, SnookersOptionsAreKnown) {
  auto c = goodCommand();
  c->option = pool_OPTION_FREE_BALL;
  EXPECT_TRUE(validateShotCommand(*c).ok()) << validateShotCommand(*c).error();
  c->speed = 0.0;
  EXPECT_EQ(validateShotCommand(*c).code(), CommandProblem::SpeedOutOfRange);
  c->option = pool_OPTION_REPLACE;
  EXPECT_TRUE(validateShotCommand(*c).ok()) << validateShotCommand(*c).error();
  setRawValue(c->option, pool_OPTION_REPLACE + 1);
  EXPECT_EQ(validateShotCommand(*c).code(), CommandProblem::BadOption);
}

TEST(ShotCommandCheck, LimitsComeFromTheCaller) {
  auto c = goodCommand();
  c->speed = 5.0;
  protocol::CommandLimits slow;
  slow.max_speed = 4.0;
  const CommandCheck check = validateShotCommand(*c, slow);
  EXPECT_EQ(check.code(), CommandProblem::SpeedOutOfRange);
  EXPECT_EQ(check.error(), "speed: must be in (0, 4] m/s");
}

}  // namespace
}  // namespace pool::net
