// The result JSON: exact layout, key order, number form, truncation and the trajectory switch.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "scenario/scenario.h"

namespace pool::scenario {
namespace {

using physics::Ball;
using physics::Event;
using physics::EventType;
using physics::MotionState;

Ball ballAt(int id, double x, double y, double z, MotionState state) {
  Ball b;
  b.id = id;
  b.pos = physics::Vec3(x, y, z);
  b.state = state;
  return b;
}

Event event(double t, EventType type, int a, int b = -1, std::string where = "") {
  Event e;
  e.t = t;
  e.type = type;
  e.ball_a = a;
  e.ball_b = b;
  e.where = std::move(where);
  return e;
}

physics::ShotOutcome smallOutcome() {
  physics::ShotOutcome o;
  o.events = {event(0.0, EventType::Strike, 0), event(0.25, EventType::BallBall, 0, 3),
              event(0.5, EventType::BallCushion, 3, -1, "foot"),
              event(0.75, EventType::Pocket, 3, -1, "foot_left_corner"),
              event(1.5, EventType::RollToRest, 0)};
  // Deliberately out of id order: the output sorts.
  o.balls = {ballAt(3, 1.2, 0.6, -0.1, MotionState::Pocketed),
             ballAt(0, 0.1, -0.0, 0.028575, MotionState::Stationary)};
  o.t_rest = 1.5;
  return o;
}

TEST(ResultJson, LayoutIsExact) {
  const std::string expected =
      "{\n"
      "  \"version\": 1,\n"
      "  \"t_rest\": 1.5,\n"
      "  \"events\": [\n"
      "    {\"t\":0.0,\"type\":\"strike\",\"balls\":[0]},\n"
      "    {\"t\":0.25,\"type\":\"ball_ball\",\"balls\":[0,3]},\n"
      "    {\"t\":0.5,\"type\":\"ball_cushion\",\"balls\":[3],\"cushion\":\"foot\"},\n"
      "    {\"t\":0.75,\"type\":\"pocket\",\"balls\":[3],\"pocket\":\"foot_left_corner\"},\n"
      "    {\"t\":1.5,\"type\":\"roll_to_rest\",\"balls\":[0]}\n"
      "  ],\n"
      "  \"balls\": [\n"
      "    {\"id\":0,\"x\":0.1,\"y\":0.0,\"z\":0.028575,\"state\":\"stationary\"},\n"
      "    {\"id\":3,\"x\":1.2,\"y\":0.6,\"z\":-0.1,\"state\":\"pocketed\"}\n"
      "  ]\n"
      "}\n";
  EXPECT_EQ(resultJson(Scenario{}, smallOutcome()), expected);
}

TEST(ResultJson, NumbersRoundTripExactly) {
  physics::ShotOutcome o = smallOutcome();
  o.t_rest = 7.429213456789012;
  o.balls[1].pos.x() = 0.1 + 0.2;  // 0.30000000000000004
  const auto j = nlohmann::json::parse(resultJson(Scenario{}, o));
  EXPECT_EQ(j["t_rest"].get<double>(), 7.429213456789012);
  EXPECT_EQ(j["balls"][0]["x"].get<double>(), 0.1 + 0.2);
}

TEST(ResultJson, TruncatedShotHasNullRestTime) {
  physics::ShotOutcome o = smallOutcome();
  o.t_rest.reset();
  o.truncated = true;
  const auto j = nlohmann::json::parse(resultJson(Scenario{}, o));
  EXPECT_TRUE(j["t_rest"].is_null());
  EXPECT_EQ(j["truncated"], true);
  EXPECT_FALSE(nlohmann::json::parse(resultJson(Scenario{}, smallOutcome())).contains("truncated"));
}

TEST(ResultJson, TrajectoryOnlyWhenAsked) {
  physics::ShotOutcome o = smallOutcome();
  physics::Sample sample;
  sample.t = 0.5;
  sample.balls = {ballAt(3, 0.4, 0.1, 0.028575, MotionState::Rolling),
                  ballAt(0, 0.2, 0.0, 0.028575, MotionState::Sliding)};
  o.trajectory = {sample};
  Scenario s;
  EXPECT_FALSE(nlohmann::json::parse(resultJson(s, o)).contains("trajectory"));
  s.options.sample_hz = 2.0;
  const auto j = nlohmann::json::parse(resultJson(s, o));
  ASSERT_EQ(j["trajectory"].size(), 1u);
  EXPECT_EQ(j["trajectory"][0]["t"], 0.5);
  EXPECT_EQ(j["trajectory"][0]["balls"][0]["id"], 0);
  EXPECT_EQ(j["trajectory"][0]["balls"][1]["id"], 3);
  EXPECT_EQ(j["trajectory"][0]["balls"][1].size(), 4u);  // id, x, y, z
}

TEST(ResultJson, EventsComeOutInTimeOrder) {
  physics::ShotOutcome o = smallOutcome();
  std::swap(o.events[1], o.events[3]);
  const auto j = nlohmann::json::parse(resultJson(Scenario{}, o));
  double last = -1.0;
  for (const auto& e : j["events"]) {
    EXPECT_GE(e["t"].get<double>(), last);
    last = e["t"].get<double>();
  }
}

TEST(ResultJson, EveryEventTypeHasItsContractName) {
  const std::vector<std::pair<EventType, std::string>> names = {
      {EventType::Strike, "strike"},
      {EventType::BallBall, "ball_ball"},
      {EventType::BallCushion, "ball_cushion"},
      {EventType::Pocket, "pocket"},
      {EventType::SlideToRoll, "slide_to_roll"},
      {EventType::RollToRest, "roll_to_rest"},
      {EventType::SpinToRest, "spin_to_rest"},
      {EventType::Airborne, "airborne"},
      {EventType::Land, "land"},
      {EventType::OffTable, "off_table"},
      {EventType::Respot, "respot"}};
  for (const auto& [type, name] : names) {
    physics::ShotOutcome o;
    o.events = {event(0.1, type, 2, type == EventType::BallBall ? 4 : -1, "x")};
    const auto j = nlohmann::json::parse(resultJson(Scenario{}, o));
    EXPECT_EQ(j["events"][0]["type"], name);
  }
}

TEST(ResultJson, NoNegativeZero) {
  physics::ShotOutcome o = smallOutcome();
  o.balls[1].pos.y() = -0.0;
  EXPECT_EQ(resultJson(Scenario{}, o).find("-0.0,"), std::string::npos);
}

}  // namespace
}  // namespace pool::scenario
