// Writing a table and a shot as scenario JSON.
#include "scenario/scenario_write.h"

#include <cmath>
#include <nlohmann/json.hpp>
#include <numbers>

namespace pool::scenario {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;  // as the parser converts (scenario_shot)

// Degrees that the parser turns back into exactly `rad` when a neighbour of the plain conversion
// does (almost always); else the plain conversion, a last bit off at most.
double degreesOf(double rad) {
  const double plain = rad * (180.0 / std::numbers::pi);
  double up = plain;
  double down = plain;
  for (int step = 0; step < 8; ++step) {
    if (up * kRadPerDeg == rad) return up;
    if (down * kRadPerDeg == rad) return down;
    up = std::nextafter(up, HUGE_VAL);
    down = std::nextafter(down, -HUGE_VAL);
  }
  return plain;
}

}  // namespace

std::string scenarioJson(const ScenarioSource& source) {
  nlohmann::ordered_json out;
  out["table"] = source.table;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& [name, value] : source.params) params[name] = value;
  out["params"] = params;
  nlohmann::ordered_json balls = nlohmann::ordered_json::array();
  for (const auto& b : source.balls) {
    if (!physics::onTable(b.state)) continue;
    balls.push_back({{"id", b.id}, {"x", b.pos.x()}, {"y", b.pos.y()}});
  }
  out["balls"] = balls;
  out["shot"] = {{"yaw_deg", degreesOf(source.shot.yaw)},
                 {"tip_side", source.shot.tip_side},
                 {"tip_height", source.shot.tip_height},
                 {"elevation_deg", degreesOf(source.shot.elevation)},
                 {"speed", source.shot.speed},
                 {"speed_is", source.shot.speed_is_ball ? "ball" : "cue"}};
  return out.dump(2) + "\n";
}

}  // namespace pool::scenario
