// Scenario texts that must be refused, with the start of their one-line reason (parser, CLI tests).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace pool::scenario::testing {

/// A legal scenario: the cue ball on the head spot, the 1 ahead of it, a 2 m/s centre hit.
inline nlohmann::json goodScenario() {
  return nlohmann::json::parse(R"({
    "table": "wpa-9ft",
    "balls": [ { "id": 0, "x": -0.635, "y": 0.0 }, { "id": 1, "x": 0.3, "y": 0.0 } ],
    "shot": { "yaw_deg": 0.0, "tip_side": 0.0, "tip_height": 0.0,
              "elevation_deg": 0.0, "speed": 2.0, "speed_is": "cue" }
  })");
}

/// goodScenario() with members (JSON pointers such as "/shot/speed") set to raw JSON text, which
/// may be something nlohmann cannot hold, such as 1e999.
inline std::string withRaws(const std::vector<std::pair<std::string, std::string>>& changes) {
  nlohmann::json j = goodScenario();
  for (std::size_t i = 0; i < changes.size(); ++i) {
    j[nlohmann::json::json_pointer(changes[i].first)] = "@RAW" + std::to_string(i) + "@";
  }
  std::string text = j.dump(2);
  for (std::size_t i = 0; i < changes.size(); ++i) {
    const std::string mark = "\"@RAW" + std::to_string(i) + "@\"";
    text.replace(text.find(mark), mark.size(), changes[i].second);
  }
  return text;
}

/// goodScenario() with one member set to raw JSON text.
inline std::string withRaw(const std::string& pointer, const std::string& raw) {
  return withRaws({{pointer, raw}});
}

/// goodScenario() without the member at `pointer`.
inline std::string without(const std::string& parent, const std::string& key) {
  nlohmann::json j = goodScenario();
  j[nlohmann::json::json_pointer(parent)].erase(key);
  return j.dump(2);
}

/// One refused input.
struct BadScenario {
  std::string name;    ///< for test output
  std::string text;    ///< the scenario file's content
  std::string reason;  ///< the expected start of the one-line reason
};

inline std::vector<BadScenario> badScenarios() {
  return {
      // The document itself.
      {"empty", "", "scenario: empty input"},
      {"blank", " \n\t\n", "scenario: empty input"},
      {"invalid_json", "{ table: wpa-9ft }", "scenario: invalid JSON"},
      {"truncated", goodScenario().dump(2).substr(0, 60), "scenario: invalid JSON"},
      {"nan_literal", withRaw("/shot/speed", "NaN"), "scenario: invalid JSON"},
      {"trailing_garbage", goodScenario().dump() + " }", "scenario: invalid JSON"},
      {"not_an_object", "[1, 2, 3]", "scenario: must be a JSON object"},
      {"duplicated_key",
       R"({"shot": {"speed": 1.0, "speed": 2.0}, "balls": [{"id": 0, "x": 0, "y": 0}]})",
       "shot.speed: duplicated key"},
      {"unknown_top_level", withRaw("/colour", "\"green\""), "colour: unknown field"},
      // Shot.
      {"missing_shot", without("", "shot"), "shot: missing"},
      {"shot_not_object", withRaw("/shot", "2.0"), "shot: must be a JSON object"},
      {"missing_speed", without("/shot", "speed"), "shot.speed: missing"},
      {"speed_string", withRaw("/shot/speed", "\"fast\""), "shot.speed: must be a number"},
      {"speed_null", withRaw("/shot/speed", "null"), "shot.speed: must be a number"},
      {"speed_bool", withRaw("/shot/speed", "true"), "shot.speed: must be a number"},
      {"speed_inf", withRaw("/shot/speed", "1e999"), "shot.speed: must be a finite number"},
      {"speed_minus_inf", withRaw("/shot/speed", "-1e999"), "shot.speed: must be a finite number"},
      {"speed_zero", withRaw("/shot/speed", "0"), "shot.speed: must be in (0, 12] m/s"},
      {"speed_negative", withRaw("/shot/speed", "-1"), "shot.speed: must be in (0, 12] m/s"},
      {"speed_too_high", withRaw("/shot/speed", "12.001"), "shot.speed: must be in (0, 12] m/s"},
      {"yaw_inf", withRaw("/shot/yaw_deg", "1e400"), "shot.yaw_deg: must be a finite number"},
      {"yaw_string", withRaw("/shot/yaw_deg", "\"east\""), "shot.yaw_deg: must be a number"},
      {"tip_side_string", withRaw("/shot/tip_side", "\"left\""), "shot.tip_side: must be a number"},
      {"tip_height_inf", withRaw("/shot/tip_height", "-1e999"),
       "shot.tip_height: must be a finite number"},
      {"elevation_negative", withRaw("/shot/elevation_deg", "-0.5"), "shot.elevation_deg:"},
      {"elevation_too_high", withRaw("/shot/elevation_deg", "89.5"), "shot.elevation_deg:"},
      {"elevation_90", withRaw("/shot/elevation_deg", "90"), "shot.elevation_deg:"},
      {"miscue_side", withRaw("/shot/tip_side", "0.51"), "shot.tip_side:"},
      {"miscue_combined", withRaws({{"/shot/tip_side", "0.4"}, {"/shot/tip_height", "0.31"}}),
       "shot.tip_side:"},
      {"miscue_ball_mode", withRaws({{"/shot/tip_height", "-0.6"}, {"/shot/speed_is", "\"ball\""}}),
       "shot.tip_side:"},
      {"miscue_lowered_limit",
       withRaws({{"/shot/tip_side", "0.3"}, {"/params", R"({"miscue_limit": 0.25})"}}),
       "shot.tip_side:"},
      {"speed_is_unknown", withRaw("/shot/speed_is", "\"tip\""), "shot.speed_is:"},
      {"speed_is_number", withRaw("/shot/speed_is", "1"), "shot.speed_is: must be a string"},
      {"shot_unknown_field", withRaw("/shot/power", "5"), "shot.power: unknown field"},
      // Table and params.
      {"unknown_table", withRaw("/table", "\"snooker-14ft\""), "table:"},
      {"table_number", withRaw("/table", "9"), "table: must be a string"},
      {"missing_table_file", withRaw("/table", "\"/nonexistent/spec.json\""), "table:"},
      {"params_not_object", withRaw("/params", "[0.2]"), "params: must be a JSON object"},
      {"unknown_param", withRaw("/params", R"({"mu": 0.2})"), "params.mu: unknown parameter"},
      {"param_string", withRaw("/params", R"({"u_s": "high"})"), "params.u_s: must be a number"},
      {"param_inf", withRaw("/params", R"({"u_s": 1e999})"), "params.u_s: must be a finite number"},
      {"param_out_of_range", withRaw("/params", R"({"u_s": -0.2})"), "params.u_s:"},
      {"models_not_object", withRaw("/models", "[1]"), "models: must be a JSON object"},
      {"unknown_model", withRaw("/models", R"({"ball_cushion": "bouncy"})"),
       "models.ball_cushion: unknown model 'bouncy'"},
      {"unknown_pair", withRaw("/models", R"({"ball_rail": "han2005"})"),
       "models.ball_rail: unknown contact pair"},
      {"param_null", withRaw("/params", R"({"e_b": null})"), "params.e_b: must be a number"},
      // Balls and rack.
      {"no_balls_no_rack", without("", "balls"), "balls: missing"},
      {"balls_not_array", withRaw("/balls", R"({"id": 0})"), "balls: must be an array"},
      {"ball_not_object", withRaw("/balls/1", "[0.3, 0.0]"), "balls[1]: must be a JSON object"},
      {"ball_id_22", withRaw("/balls/1/id", "22"), "balls[1].id: must be an integer in [0, 21]"},
      {"ball_id_negative", withRaw("/balls/1/id", "-1"),
       "balls[1].id: must be an integer in [0, 21]"},
      {"ball_id_fraction", withRaw("/balls/1/id", "1.5"),
       "balls[1].id: must be an integer in [0, 21]"},
      {"ball_id_string", withRaw("/balls/1/id", "\"one\""),
       "balls[1].id: must be an integer in [0, 21]"},
      {"ball_id_missing", without("/balls/1", "id"), "balls[1].id: missing"},
      {"ball_id_twice", withRaw("/balls/1/id", "0"), "balls[1].id: ball 0 is listed twice"},
      {"ball_x_missing", without("/balls/1", "x"), "balls[1].x: missing"},
      {"ball_x_string", withRaw("/balls/1/x", "\"0.3\""), "balls[1].x: must be a number"},
      {"ball_y_inf", withRaw("/balls/1/y", "1e999"), "balls[1].y: must be a finite number"},
      {"ball_z_given", withRaw("/balls/1/z", "0.03"), "balls[1].z: unknown field"},
      {"ball_inside_another", withRaw("/balls/1/x", "-0.6"), "balls: ball 0 overlaps ball 1"},
      {"ball_on_same_spot", withRaw("/balls/1/x", "-0.635"), "balls: ball 0 overlaps ball 1"},
      {"ball_off_slate_x", withRaw("/balls/1/x", "1.5"), "balls: ball 1 is off the slate"},
      {"ball_off_slate_y", withRaw("/balls/1/y", "-0.64"), "balls: ball 1 is off the slate"},
      {"ball_in_cushion", withRaw("/balls/1/y", "0.62"), "balls: ball 1 is off the slate"},
      {"no_cue_ball", withRaw("/balls/0/id", "2"), "balls: no cue ball (id 0)"},
      {"rack_unknown", withRaw("/rack", "\"11ball\""),
       "rack: must be \"8ball\", \"9ball\" or \"10ball\""},
      {"rack_number", withRaw("/rack", "8"), "rack: must be \"8ball\", \"9ball\" or \"10ball\""},
      {"rack_and_ball_overlap",
       withRaws({{"/rack", "\"9ball\""}, {"/balls/1", R"({"id": 10, "x": 0.64, "y": 0.0})"}}),
       "balls: ball 1 overlaps ball 10"},
      // Options.
      {"seed_negative", withRaw("/seed", "-1"), "seed: must be an integer"},
      {"seed_fraction", withRaw("/seed", "0.5"), "seed: must be an integer"},
      {"seed_string", withRaw("/seed", "\"abc\""), "seed: must be an integer"},
      {"max_time_zero", withRaw("/max_time", "0"),
       "max_time: must be a finite number in (0, 3600]"},
      {"max_time_inf", withRaw("/max_time", "1e999"), "max_time: must be a finite number"},
      {"trajectory_hz_negative", withRaw("/trajectory_hz", "-1"),
       "trajectory_hz: must be a finite number in [0, 1000]"},
      {"trajectory_hz_string", withRaw("/trajectory_hz", "\"fast\""),
       "trajectory_hz: must be a finite number"},
      {"description_number", withRaw("/description", "1"), "description: must be a string"},
  };
}

}  // namespace pool::scenario::testing

namespace pool::scenario::testing {

/// Values at the very edge of what is legal.
inline std::vector<std::pair<std::string, std::string>> edgeScenarios() {
  return {
      {"speed_12", withRaw("/shot/speed", "12")},
      {"speed_tiny", withRaw("/shot/speed", "0.001")},
      {"elevation_89", withRaw("/shot/elevation_deg", "89")},
      {"elevation_0", withRaw("/shot/elevation_deg", "0")},
      {"tip_side_at_limit", withRaw("/shot/tip_side", "0.5")},
      {"tip_height_at_minus_limit", withRaw("/shot/tip_height", "-0.5")},
      {"tip_3_4_5_at_limit", withRaws({{"/shot/tip_side", "0.3"}, {"/shot/tip_height", "0.4"}})},
      {"ball_mode_at_limit",
       withRaws({{"/shot/tip_side", "-0.5"}, {"/shot/speed_is", "\"ball\""}})},
      {"raised_limit",
       withRaws({{"/shot/tip_side", "0.55"}, {"/params", R"({"miscue_limit": 0.6})"}})},
      {"balls_touching", withRaw("/balls/1/x", "-0.57785")},
      {"seed_max", withRaw("/seed", "18446744073709551615")},
      {"max_time_3600", withRaw("/max_time", "3600")},
      {"trajectory_hz_1000", withRaw("/trajectory_hz", "1000")},
      {"yaw_large", withRaw("/shot/yaw_deg", "-720")},
      {"integral_float_x", withRaw("/balls/1/x", "0")},
      {"description", withRaw("/description", "\"a note for people\"")},
  };
}

}  // namespace pool::scenario::testing
