// The scenario's balls: a rack and/or explicit positions, the cue ball, the placement check.
#include <algorithm>
#include <map>

#include "physics/simulation.h"
#include "scenario/object_reader.h"
#include "scenario/scenario_sections.h"
#include "table/rack.h"

namespace pool::scenario {
namespace {

using Positions = std::map<int, Eigen::Vector2d>;  // by id: sorted, one entry per id

// One entry of `balls`: {"id": 3, "x": 0.1, "y": -0.2}.
Check<> readBallEntry(const nlohmann::json& entry, const std::string& path, Positions& placed) {
  ObjectReader reader(entry, path);
  reader.onlyKnown({"id", "x", "y"});
  int id = 0;
  Eigen::Vector2d pos = Eigen::Vector2d::Zero();
  reader.integer("id", 0, physics::kMaxBallId, id, Presence::Required);
  reader.number("x", pos.x(), Presence::Required);
  reader.number("y", pos.y(), Presence::Required);
  if (reader.ok() && placed.count(id) != 0)
    reader.fail("id", "ball " + std::to_string(id) + " is listed twice");
  if (!reader.ok()) return reader.check();
  placed[id] = pos;
  return Check<>::pass();
}

Check<> readBallList(const nlohmann::json& balls, Positions& placed) {
  if (!balls.is_array())
    return Check<>::refuse("not_an_array", "balls: must be an array, got " + shortDump(balls));
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (auto ok = readBallEntry(balls[i], indexPath("balls", i), placed); !ok) return ok;
  }
  return Check<>::pass();
}

// The rack's object balls, and the cue ball on the head spot.
Check<> readRack(const nlohmann::json& rack, Scenario& s, Positions& racked) {
  const auto type =
      rack.is_string() ? table::rackTypeFromString(rack.get<std::string>()) : std::nullopt;
  if (!type)
    return Check<>::refuse(
        "bad_rack", "rack: must be \"8ball\", \"9ball\" or \"10ball\", got " + shortDump(rack));
  const double r = s.spec.params.ball_radius;
  for (const auto& b : table::rackFor(*type, s.spec, r, s.seed, s.rack_generator))
    racked[b.id] = b.pos;
  racked[physics::kCueBall] = table::spotsFor(s.spec).head_spot;
  return Check<>::pass();
}

std::vector<physics::Ball> ballsAtRest(const Positions& positions, double radius) {
  std::vector<physics::Ball> out;
  for (const auto& [id, xy] : positions) {
    physics::Ball b;
    b.id = id;
    b.pos = physics::Vec3(xy.x(), xy.y(), radius);
    out.push_back(b);
  }
  return out;
}

}  // namespace

Check<> readBalls(const nlohmann::json* balls, const nlohmann::json* rack, Scenario& s) {
  if (balls == nullptr && rack == nullptr)
    return Check<>::refuse("no_balls", "balls: missing (a scenario needs `balls`, `rack` or both)");
  Positions positions;
  if (rack != nullptr) {
    if (auto ok = readRack(*rack, s, positions); !ok) return ok;
  }
  if (balls != nullptr) {
    Positions placed;
    if (auto ok = readBallList(*balls, placed); !ok) return ok;
    for (const auto& [id, xy] : placed) positions[id] = xy;  // explicit positions win over the rack
  }
  if (positions.count(physics::kCueBall) == 0)
    return Check<>::refuse("no_cue_ball", "balls: no cue ball (id 0)");
  s.balls = ballsAtRest(positions, s.spec.params.ball_radius);
  const auto ok = physics::checkPlacement(s.balls, s.geometry, s.spec.params);
  if (!ok) return Check<>::refuse(ok.code(), "balls: " + ok.error());
  return Check<>::pass();
}

}  // namespace pool::scenario
