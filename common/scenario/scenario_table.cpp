// The scenario's table: spec by name or path, coefficient and model overrides (`params`,
// `models`), collision geometry.
#include <algorithm>
#include <filesystem>
#include <system_error>

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

std::string readTable(const std::string& name_or_path, const std::filesystem::path& base_dir,
                      Scenario& s) {
  if (name_or_path.empty())
    return "table: must be a table name (wpa-9ft, wpa-8ft, wpa-7ft) or a spec file path";
  auto spec = table::loadTableSpec(resolveTable(name_or_path, base_dir));
  if (!spec) return "table: " + spec.error();
  s.spec = std::move(*spec);
  return "";
}

std::string readParams(const nlohmann::json* params, Scenario& s) {
  if (params != nullptr) {
    ObjectReader reader(*params, "params");
    if (!reader.ok()) return reader.error();
    for (const auto& item : params->items()) {
      const auto& names = table::paramNames();
      if (std::find(names.begin(), names.end(), item.key()) == names.end()) {
        reader.fail(item.key(), "unknown parameter");
        break;
      }
      double value = 0.0;
      reader.number(item.key(), value, Presence::Required);
      if (!reader.ok()) break;
      if (const std::string why = table::setParam(s.spec.params, item.key(), value); !why.empty()) {
        reader.fail(item.key(), why);
      }
    }
    if (!reader.ok()) return reader.error();
  }
  const std::string why = table::validate(s.spec.params);
  return why.empty() ? "" : "params." + why;
}

std::string readModels(const nlohmann::json* models, Scenario& s) {
  if (models == nullptr) return "";
  ObjectReader reader(*models, "models");
  if (!reader.ok()) return reader.error();
  for (const auto& item : models->items()) {
    std::string name;
    reader.string(item.key(), name, Presence::Required);
    if (!reader.ok()) break;
    if (const std::string why = table::setModel(s.spec.models, item.key(), name); !why.empty()) {
      reader.fail(item.key(), why);
    }
  }
  return reader.error();
}

std::string buildGeometry(Scenario& s) {
  // The collision mesh through assimp, as the server reads it; a spec without one (or whose mesh
  // file is not beside it) gets the same geometry generated from the spec, as pool-tablegen
  // would write it. Coefficient overrides (cushion_height, ball_radius) need no new mesh: the
  // physics reads the nose height and the radius from the params.
  std::error_code ec;
  if (s.spec.collision_mesh.empty() || !std::filesystem::exists(s.spec.collision_mesh, ec)) {
    s.geometry = table::buildTableGeometry(s.spec);
    return "";
  }
  auto loaded = table::loadTableGeometry(s.spec);
  if (!loaded) return "table: " + loaded.error();
  s.geometry = std::move(*loaded);
  return "";
}

}  // namespace pool::scenario
