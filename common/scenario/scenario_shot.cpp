// The scenario's shot: degrees and tip offsets at the edge, a validated CueShot (radians) inside.
#include <cmath>
#include <numbers>
#include <string>
#include <string_view>
#include <utility>

#include "physics/cue_strike.h"
#include "scenario/object_reader.h"
#include "scenario/scenario_sections.h"

namespace pool::scenario {
namespace {

constexpr double kRadPerDeg = std::numbers::pi / 180.0;

// The physics' check names a shot's values as the physics does ("elevation: ..."); a scenario's
// error names the file's own field ("shot.elevation_deg: ...").
std::string inScenarioTerms(const std::string& sentence) {
  static const std::pair<std::string_view, std::string_view> kFields[] = {
      {"tip_side, tip_height", "tip_side"},
      {"elevation", "elevation_deg"},
      {"yaw", "yaw_deg"},
  };
  const auto colon = sentence.find(": ");
  const std::string_view field = std::string_view(sentence).substr(0, colon);
  for (const auto& [physics, scenario] : kFields) {
    if (field == physics) return "shot." + std::string(scenario) + sentence.substr(colon);
  }
  return "shot." + sentence;
}

}  // namespace

Check<> readShot(const nlohmann::json& shot, Scenario& s) {
  ObjectReader reader(shot, "shot");
  reader.onlyKnown({"yaw_deg", "tip_side", "tip_height", "elevation_deg", "speed", "speed_is"});
  double yaw_deg = 0.0;
  double elevation_deg = 0.0;
  std::string speed_is = "cue";
  physics::CueShot cue;
  reader.number("yaw_deg", yaw_deg);
  reader.number("tip_side", cue.tip_side);
  reader.number("tip_height", cue.tip_height);
  reader.number("elevation_deg", elevation_deg);
  reader.number("speed", cue.speed, Presence::Required);
  reader.string("speed_is", speed_is);
  // A heading is an angle: a few turns either way are still one (-720 runs), but 1e308 is no
  // heading at all and would reach the physics.
  if (reader.ok() && !(std::abs(yaw_deg) <= 3600.0)) {
    reader.fail("yaw_deg", "must be within -3600 to 3600 degrees, got " + shortDump(yaw_deg));
  }
  if (reader.ok() && speed_is != "cue" && speed_is != "ball") {
    reader.fail("speed_is", "must be \"cue\" or \"ball\", got " + shortDump(speed_is));
  }
  if (!reader.ok()) return reader.check();
  cue.yaw = yaw_deg * kRadPerDeg;
  cue.elevation = elevation_deg * kRadPerDeg;
  cue.speed_is_ball = speed_is == "ball";
  if (auto ok = physics::validateShot(cue, s.spec.params); !ok) {
    return Check<>::refuse(physics::toString(ok.code()), inScenarioTerms(ok.error()));
  }
  s.shot = cue;
  return Check<>::pass();
}

}  // namespace pool::scenario
