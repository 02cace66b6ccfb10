// Writing a table and a shot as scenario JSON.
#include "scenario/scenario_write.h"

#include <nlohmann/json.hpp>
#include <numbers>

namespace pool::scenario {

std::string scenarioJson(const ScenarioSource& source) {
  constexpr double kDegPerRad = 180.0 / std::numbers::pi;
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
  out["shot"] = {{"yaw_deg", source.shot.yaw * kDegPerRad},
                 {"tip_side", source.shot.tip_side},
                 {"tip_height", source.shot.tip_height},
                 {"elevation_deg", source.shot.elevation * kDegPerRad},
                 {"speed", source.shot.speed},
                 {"speed_is", source.shot.speed_is_ball ? "ball" : "cue"}};
  return out.dump(2) + "\n";
}

}  // namespace pool::scenario
