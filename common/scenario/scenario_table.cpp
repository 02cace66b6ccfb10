// The scenario's table: spec by name or path, coefficient and model overrides (`params`,
// `models`), collision geometry.
#include <algorithm>
#include <filesystem>
#include <system_error>

#include "game/loaded_table.h"
#include "scenario/object_reader.h"
#include "scenario/scenario_sections.h"
#include "table/contact_models.h"
#include "table/physics_params.h"

namespace pool::scenario {
namespace {

// Names such as "wpa-9ft" go to the table loader as they are; paths may be relative to base_dir.
std::string resolveTable(const std::string& name_or_path, const std::filesystem::path& base_dir) {
  const std::filesystem::path p(name_or_path);
  const bool looks_like_path =
      name_or_path.find('/') != std::string::npos || p.extension() == ".json";
  if (!looks_like_path || p.is_absolute() || base_dir.empty()) return name_or_path;
  std::error_code ec;
  const auto beside = base_dir / p;
  return std::filesystem::is_regular_file(beside, ec) ? beside.string() : name_or_path;
}

}  // namespace

Check<> readTable(const std::string& name_or_path, const std::filesystem::path& base_dir,
                  Scenario& s) {
  if (name_or_path.empty())
    return Check<>::refuse(
        "bad_table", "table: must be a table name (wpa-9ft, wpa-8ft, wpa-7ft) or a spec file path");
  auto spec = table::loadTableSpec(resolveTable(name_or_path, base_dir));
  if (!spec) return Check<>::refuse("bad_table", "table: " + spec.error());
  s.spec = std::move(*spec);
  return Check<>::pass();
}

Check<> readParams(const nlohmann::json* params, Scenario& s) {
  if (params != nullptr) {
    ObjectReader reader(*params, "params");
    if (!reader.ok()) return reader.check();
    for (const auto& item : params->items()) {
      const auto& names = table::paramNames();
      if (std::find(names.begin(), names.end(), item.key()) == names.end()) {
        reader.fail(item.key(), "unknown parameter");
        break;
      }
      double value = 0.0;
      reader.number(item.key(), value, Presence::Required);
      if (!reader.ok()) break;
      if (auto ok = table::setParam(s.spec.params, item.key(), value); !ok) {
        reader.fail(item.key(), ok.error());
      }
    }
    if (!reader.ok()) return reader.check();
  }
  const auto ok = table::validate(s.spec.params);
  if (!ok) return Check<>::refuse(ok.code(), "params." + ok.error());
  return Check<>::pass();
}

Check<> readModels(const nlohmann::json* models, Scenario& s) {
  if (models == nullptr) return Check<>::pass();
  ObjectReader reader(*models, "models");
  if (!reader.ok()) return reader.check();
  for (const auto& item : models->items()) {
    std::string name;
    reader.string(item.key(), name, Presence::Required);
    if (!reader.ok()) break;
    if (auto ok = table::setModel(s.spec.models, item.key(), name); !ok) {
      reader.fail(item.key(), ok.error());
    }
  }
  return reader.check();
}

Check<> buildGeometry(Scenario& s) {
  // The game kit's geometry of a spec: the collision mesh through assimp, as the server reads it,
  // or for a spec without one (or whose mesh file is not beside it) the same geometry generated
  // from the spec. Coefficient overrides (cushion_height, ball_radius) need no
  // new mesh: the physics reads the nose height and the radius from the params.
  auto geometry = game::tableGeometry(s.spec);
  if (!geometry) return Check<>::refuse("bad_table", "table: " + geometry.error());
  s.geometry = std::move(*geometry);
  return Check<>::pass();
}

}  // namespace pool::scenario
