// A cue shot as JSON: its six fields under their names, the numbers as they are held.
#include "scenario/cue_shot_json.h"

#include <gtest/gtest.h>

namespace pool::scenario {
namespace {

TEST(CueShotJson, SixFieldsUnderTheirNames) {
  physics::CueShot shot;
  shot.yaw = 0.1;
  shot.tip_side = -0.25;
  shot.tip_height = 0.3;
  shot.elevation = 0.05;
  shot.speed = 4.5;
  shot.speed_is_ball = true;
  EXPECT_EQ(cueShotJson(shot).dump(),
            R"({"elevation":0.05,"speed":4.5,"speed_is_ball":true,"tip_height":0.3,)"
            R"("tip_side":-0.25,"yaw":0.1})");
}

TEST(CueShotJson, CallersAddTheirOwnKeys) {
  nlohmann::json line{{"event", "shot"}, {"seq", 3}};
  line.update(cueShotJson(physics::CueShot{}));
  EXPECT_EQ(line.size(), 8u);
  EXPECT_EQ(line.at("event"), "shot");
  EXPECT_EQ(line.at("speed_is_ball"), false);
}

}  // namespace
}  // namespace pool::scenario
