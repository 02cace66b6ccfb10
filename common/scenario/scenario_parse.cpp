// Scenario files (SIM-CONTRACT.md): the top-level fields, their defaults, the order of checks.
#include "scenario/json_document.h"
#include "scenario/object_reader.h"
#include "scenario/scenario_sections.h"

namespace pool::scenario {
namespace {

constexpr Interval kMaxTime{0.0, 3600.0, true};        // s
constexpr Interval kTrajectoryHz{0.0, 1000.0, false};  // 0 = no trajectory

// The scalar top-level fields; the sections follow once these are known.
struct TopLevel {
  std::string table = "wpa-9ft";
  const nlohmann::json* params = nullptr;
  const nlohmann::json* models = nullptr;
  const nlohmann::json* balls = nullptr;
  const nlohmann::json* rack = nullptr;
  const nlohmann::json* shot = nullptr;
};

Check<> readTopLevel(const nlohmann::json& doc, TopLevel& top, Scenario& s) {
  ObjectReader reader(doc, "");
  reader.onlyKnown({"description", "table", "params", "models", "balls", "rack", "rack_gaps",
                    "shot", "seed", "max_time", "trajectory_hz"});
  std::string description;  // free text for people; not used
  reader.string("description", description);
  reader.string("table", top.table);
  top.params = reader.member("params");
  top.models = reader.member("models");
  top.balls = reader.member("balls");
  top.rack = reader.member("rack");
  top.shot = reader.member("shot", Presence::Required);
  std::string gaps = "frozen";
  reader.string("rack_gaps", gaps);
  if (gaps == "hand") {
    s.rack_generator = table::RackGenerator::Hand;
  } else if (gaps != "frozen") {
    reader.fail("rack_gaps", "must be \"frozen\" or \"hand\"");
  }
  reader.unsignedInteger("seed", s.seed);
  reader.numberIn("max_time", kMaxTime, s.options.max_time);
  reader.numberIn("trajectory_hz", kTrajectoryHz, s.options.sample_hz);
  return reader.check();
}

}  // namespace

Result<Scenario> parseScenarioIn(const std::string& json_text,
                                 const std::filesystem::path& base_dir) {
  auto doc = parseJsonDocument(json_text);
  if (!doc) return Result<Scenario>::fail(doc.error());
  Scenario s;
  TopLevel top;
  Check<> ok = readTopLevel(*doc, top, s);
  // Each step needs the ones before it: params change the spec, the geometry needs the params...
  if (ok) ok = readTable(top.table, base_dir, s);
  if (ok) ok = readParams(top.params, s);
  if (ok) ok = readModels(top.models, s);
  if (ok) ok = buildGeometry(s);
  if (ok) ok = readBalls(top.balls, top.rack, s);
  if (ok) ok = readShot(*top.shot, s);
  if (!ok) return Result<Scenario>::fail(ok.code(), oneLine(ok.error()));
  return Result<Scenario>::ok(std::move(s));
}

Result<Scenario> parseScenario(const std::string& json_text) {
  return parseScenarioIn(json_text, {});
}

}  // namespace pool::scenario
