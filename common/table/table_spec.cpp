// Reads table specs from JSON (by shipped name or path), with one-line reasons naming the bad
// field.
//
// Mesh paths in a spec ("collision_mesh", "render_mesh") are relative to the spec file's folder
// (absolute paths are kept); both are optional, render_mesh defaults to collision_mesh.
#include "table/table_spec.h"

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/input_file.h"
#include "core/text.h"
#include "table/assets.h"
#include "table/table_layout.h"

namespace pool::table {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

/// A numeric field's rule and the reason given when it is broken.
struct NumberRule {
  bool (*ok)(double);
  const char* reason;
};

const NumberRule kPositive{[](double v) { return v > 0.0; }, "must be a finite number > 0"};
const NumberRule kAnyFinite{[](double) { return true; }, "must be a finite number"};
const NumberRule kSlate{[](double v) { return v > 0.0 && v <= 0.05; },
                        "must be a finite number in (0, 0.05]"};
const NumberRule kJawAngle{[](double v) { return v > 90.0 && v < 180.0; },
                           "must be a finite number in (90, 180)"};

struct NumberField {
  const char* key;
  double* target;
  const NumberRule* rule;
};

/// Reads the listed numbers from `obj`, then rejects keys that are neither listed nor in
/// `other_known`, or refuses with a reason.
Check<> readFields(const json& obj, const std::string& prefix,
                   std::initializer_list<NumberField> fields,
                   std::initializer_list<const char*> other_known) {
  for (const NumberField& f : fields) {
    const auto it = obj.find(f.key);
    const std::string where = prefix + f.key + ": ";
    if (it == obj.end())
      return Check<>::refuse("missing_field", where + "missing (" + f.rule->reason + ")");
    if (!it->is_number()) return Check<>::refuse("bad_number", where + f.rule->reason);
    const double v = it->get<double>();
    if (!std::isfinite(v) || !f.rule->ok(v))
      return Check<>::refuse("bad_number", where + f.rule->reason);
    *f.target = v;
  }
  for (const auto& [key, value] : obj.items()) {
    bool known = false;
    for (const NumberField& f : fields) known = known || key == f.key;
    for (const char* k : other_known) known = known || key == k;
    if (!known)
      return Check<>::refuse("unknown_field", prefix + escapedForLog(key) + ": unknown field");
  }
  return Check<>::pass();
}

Check<> readPocket(const json& root, const char* key, PocketSpec& out) {
  const auto it = root.find(key);
  const std::string prefix = std::string(key) + ".";
  if (it == root.end())
    return Check<>::refuse("missing_field", std::string(key) + ": missing (must be an object)");
  if (!it->is_object())
    return Check<>::refuse("not_an_object", std::string(key) + ": must be an object");
  return readFields(*it, prefix,
                    {{"mouth", &out.mouth, &kPositive},
                     {"jaw_angle_deg", &out.jaw_angle_deg, &kJawAngle},
                     {"hole_radius", &out.hole_radius, &kPositive},
                     {"hole_offset", &out.hole_offset, &kAnyFinite}},
                    {});
}

/// `pockets` (true unless false), then the corner and side pockets where there are pockets; a
/// table without them must not describe any.
Check<> readPockets(const json& root, TableSpec& spec) {
  if (const auto it = root.find("pockets"); it != root.end()) {
    if (!it->is_boolean()) return Check<>::refuse("not_a_bool", "pockets: must be true or false");
    spec.pockets = it->get<bool>();
  }
  if (!spec.pockets) {
    for (const char* key : {"corner", "side"}) {
      if (root.contains(key))
        return Check<>::refuse("pocket_without_pockets",
                               std::string(key) + ": a table without pockets has no pocket spec");
    }
    return Check<>::pass();
  }
  if (auto r = readPocket(root, "corner", spec.corner); !r) return r;
  return readPocket(root, "side", spec.side);
}

Check<> readSnookerMarks(const json& root, std::optional<SnookerMarks>& out) {
  const auto it = root.find("snooker_marks");
  if (it == root.end()) return Check<>::pass();
  if (!it->is_object()) return Check<>::refuse("not_an_object", "snooker_marks: must be an object");
  SnookerMarks m;
  if (auto r = readFields(*it, "snooker_marks.",
                          {{"baulk_line", &m.baulk_line, &kPositive},
                           {"d_radius", &m.d_radius, &kPositive},
                           {"black_spot", &m.black_spot, &kPositive}},
                          {});
      !r)
    return r;
  out = m;
  return Check<>::pass();
}

Check<> readParams(const json& root, PhysicsParams& params) {
  const auto it = root.find("params");
  if (it == root.end()) return Check<>::pass();
  if (!it->is_object()) return Check<>::refuse("not_an_object", "params: must be an object");
  for (const auto& [key, value] : it->items()) {
    const std::string where = "params." + escapedForLog(key) + ": ";
    if (key == "u_b" && value.is_null()) {
      params.u_b.reset();
      continue;
    }
    const double v = value.is_number() ? value.get<double>() : std::nan("");
    if (auto ok = setParam(params, key, v); !ok)
      return Check<>::refuse(ok.code(), where + ok.error());
  }
  if (auto ok = validate(params); !ok) return Check<>::refuse(ok.code(), "params." + ok.error());
  return Check<>::pass();
}

Check<> readModels(const json& root, ContactModels& models) {
  const auto it = root.find("models");
  if (it == root.end()) return Check<>::pass();
  if (!it->is_object()) return Check<>::refuse("not_an_object", "models: must be an object");
  for (const auto& [key, value] : it->items()) {
    if (!value.is_string())
      return Check<>::refuse("not_a_string", "models." + escapedForLog(key) + ": must be a string");
    if (auto ok = setModel(models, key, value.get<std::string>()); !ok)
      return Check<>::refuse(ok.code(), "models." + escapedForLog(key) + ": " + ok.error());
  }
  return Check<>::pass();
}

/// Reads an optional string field, or refuses it with a reason.
Check<> readString(const json& root, const char* key, std::string& out) {
  const auto it = root.find(key);
  if (it == root.end()) return Check<>::pass();
  if (!it->is_string())
    return Check<>::refuse("not_a_string", std::string(key) + ": must be a string");
  out = it->get<std::string>();
  return Check<>::pass();
}

fs::path resolveMesh(const std::string& text, const fs::path& spec_dir) {
  if (text.empty()) return {};
  const fs::path p(text);
  return (p.is_absolute() ? p : spec_dir / p).lexically_normal();
}

/// Checks that one pocket kind fits a ball and its hole neither reaches the jaws nor leaves the
/// slate.
Check<> checkPocket(const TableSpec& spec, const char* key, const PocketSpec& pocket, bool corner) {
  const double r = spec.params.ball_radius;
  const std::string where = std::string(key) + ".";
  if (pocket.mouth <= 2.0 * r)
    return Check<>::refuse("pocket_too_narrow",
                           where + "mouth: must be wider than a ball (2 * ball_radius)");
  if (pocket.hole_radius <= r)
    return Check<>::refuse("hole_too_small",
                           where + "hole_radius: must be larger than ball_radius");
  const Eigen::Vector2d outer = detail::slateHalfExtent(spec);
  const std::vector<detail::PocketLayout> pockets = detail::pocketLayouts(spec);
  for (const detail::PocketLayout& p : pockets) {
    if (p.corner != corner) continue;
    for (int k = 0; k < 2; ++k) {
      if (std::abs(p.hole_centre[k]) + p.hole_radius + detail::kEdgeMargin >= outer[k]) {
        return Check<>::refuse("hole_beyond_rail",
                               where + "hole_radius: the hole reaches beyond the rail");
      }
    }
  }
  for (const detail::JawLayout& j : detail::jawLayouts(spec)) {
    const detail::PocketLayout& p = pockets[static_cast<std::size_t>(j.pocket)];
    if (p.corner == corner && (p.hole_centre - j.point).norm() <= p.hole_radius) {
      return Check<>::refuse("hole_reaches_jaws",
                             where + "hole_radius: the hole reaches the jaw points");
    }
  }
  return Check<>::pass();
}

/// Checks that rails have positive length and the pockets' slate tiles do not overlap.
Check<> checkLayout(const TableSpec& spec) {
  const double s = spec.corner.mouth / std::sqrt(2.0);
  if (spec.length / 2.0 - s - spec.side.mouth / 2.0 <= 0.0)
    return Check<>::refuse("too_short", "length: too short for its pockets");
  if (spec.width / 2.0 - s <= 0.0)
    return Check<>::refuse("too_narrow", "width: too narrow for its pockets");
  const auto pockets = detail::pocketLayouts(spec);
  for (std::size_t i = 0; i < pockets.size(); ++i) {
    for (std::size_t k = i + 1; k < pockets.size(); ++k) {
      const detail::Tile a = detail::holeTile(spec, pockets[i]);
      const detail::Tile b = detail::holeTile(spec, pockets[k]);
      const bool apart_x = a.max.x() <= b.min.x() || b.max.x() <= a.min.x();
      const bool apart_y = a.max.y() <= b.min.y() || b.max.y() <= a.min.y();
      if (!apart_x && !apart_y) {
        const bool same_end = pockets[i].reference.x() == pockets[k].reference.x();
        return same_end ? Check<>::refuse("too_narrow", "width: too narrow for its pockets")
                        : Check<>::refuse("too_short", "length: too short for its pockets");
      }
    }
  }
  return Check<>::pass();
}

Check<> checkSpec(const TableSpec& spec) {
  if (spec.snooker_marks) {
    const SnookerMarks& m = *spec.snooker_marks;
    if (m.baulk_line + m.black_spot >= spec.length)
      return Check<>::refuse("marks_overlap",
                             "snooker_marks: the baulk line and the black spot must leave room "
                             "between them");
    if (m.d_radius >= spec.width / 2.0)
      return Check<>::refuse("d_too_wide", "snooker_marks.d_radius: must be less than width / 2");
  }
  if (!spec.pockets) return Check<>::pass();
  if (auto r = checkLayout(spec); !r) return r;
  if (auto r = checkPocket(spec, "corner", spec.corner, true); !r) return r;
  return checkPocket(spec, "side", spec.side, false);
}

/// Fills `spec` from the parsed root object, or refuses it with a reason.
Check<> readSpec(const json& root, const fs::path& spec_dir, TableSpec& spec) {
  Check<> r = readFields(root, "",
                         {{"length", &spec.length, &kPositive},
                          {"width", &spec.width, &kPositive},
                          {"cushion_width", &spec.cushion_width, &kPositive},
                          {"rail_width", &spec.rail_width, &kPositive},
                          {"slate_thickness", &spec.slate_thickness, &kSlate}},
                         {"name", "description", "pockets", "corner", "side", "snooker_marks",
                          "params", "models", "collision_mesh", "render_mesh"});
  if (!r) return r;
  std::string description, collision, render;
  for (const auto& [key, target] :
       {std::pair{"name", &spec.name}, std::pair{"description", &description},
        std::pair{"collision_mesh", &collision}, std::pair{"render_mesh", &render}}) {
    if (r = readString(root, key, *target); !r) return r;
  }
  if (r = readPockets(root, spec); !r) return r;
  if (r = readSnookerMarks(root, spec.snooker_marks); !r) return r;
  if (r = readParams(root, spec.params); !r) return r;
  if (r = readModels(root, spec.models); !r) return r;
  spec.collision_mesh = resolveMesh(collision, spec_dir);
  spec.render_mesh = render.empty() ? spec.collision_mesh : resolveMesh(render, spec_dir);
  return checkSpec(spec);
}

bool looksLikePath(const std::string& s) {
  return s.find('/') != std::string::npos || (s.size() > 5 && s.ends_with(".json"));
}

/// Strips nlohmann's "[json.exception...] " prefix from an error message.
std::string shortWhat(const std::exception& e) {
  std::string what = e.what();
  if (const auto pos = what.find("] "); what.starts_with("[json.") && pos != std::string::npos) {
    what = what.substr(pos + 2);
  }
  return what;
}

Result<TableSpec> loadFile(const fs::path& path, const std::string& default_name) {
  // A device (/dev/zero) or a huge file would be read whole before JSON could refuse it.
  const auto text = readInputFile(path);
  if (!text) {
    return Result<TableSpec>::fail(path.string() + ": cannot read the spec file: " + text.error());
  }
  return parseTableSpec(*text, path.string(), fs::absolute(path).parent_path(), default_name);
}

}  // namespace

Result<TableSpec> parseTableSpec(const std::string& json_text, const std::string& source,
                                 const fs::path& spec_dir, const std::string& default_name) {
  TableSpec spec;
  spec.name = default_name;
  try {
    const json root = json::parse(json_text);
    if (!root.is_object())
      return Result<TableSpec>::fail(source + ": the spec must be a JSON object");
    if (auto ok = readSpec(root, spec_dir, spec); !ok) return Result<TableSpec>::fail(ok.error());
  } catch (const std::exception& e) {
    return Result<TableSpec>::fail(source + ": invalid JSON: " + shortWhat(e));
  }
  return Result<TableSpec>::ok(std::move(spec));
}

bool isSpecName(const std::string& name) {
  if (name.empty() || name.size() > 32) return false;
  for (const char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= '0' && c <= '9') || c == '-';
    if (!ok) return false;
  }
  return true;
}

Result<TableSpec> loadTableSpec(const std::string& nameOrPath) {
  if (nameOrPath.empty()) return Result<TableSpec>::fail("empty table name");
  if (looksLikePath(nameOrPath))
    return loadFile(fs::path(nameOrPath), fs::path(nameOrPath).stem().string());
  const auto found = findAsset("tables/" + nameOrPath + ".json");
  if (!found) {
    return Result<TableSpec>::fail(
        "unknown table '" + nameOrPath +
        "' (expected wpa-9ft, wpa-8ft, wpa-7ft, snooker-12ft, carom-match or a path to a "
        "spec file)");
  }
  return loadFile(*found, nameOrPath);
}

}  // namespace pool::table
