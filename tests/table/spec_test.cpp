// Table specs: the shipped tables, bad spec files with their one-line reasons, coefficient ranges.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <nlohmann/json.hpp>
#include <string>

#include "table/contact_models.h"
#include "table/physics_params.h"
#include "table/table_spec.h"

namespace pool::table {
namespace {

namespace fs = std::filesystem;
using json = nlohmann::json;

const fs::path kTablesDir = fs::path(POOL_SOURCE_DIR) / "assets" / "tables";

json shippedJson(const std::string& name) {
  std::ifstream in(kTablesDir / (name + ".json"));
  return json::parse(in);
}

/// A scratch folder per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / ("pool_table_test_" + std::string(info->name()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  const fs::path& path() const { return path_; }

  fs::path write(const std::string& file, const std::string& text) const {
    std::ofstream(path_ / file, std::ios::binary) << text;
    return path_ / file;
  }

 private:
  fs::path path_;
};

/// Loads the 9-ft spec after `edit` changed its JSON; returns the failure reason ("" on success).
template <class Edit>
std::string reasonAfter(const TempDir& dir, Edit edit) {
  json j = shippedJson("wpa-9ft");
  edit(j);
  const auto spec = loadTableSpec(dir.write("spec.json", j.dump(2)).string());
  return spec ? "" : spec.error();
}

struct Dimensions {
  const char* name;
  double length;
  double width;
};

TEST(TableSpec, LoadsTheShippedTablesByName) {
  for (const Dimensions& d :
       {Dimensions{"wpa-9ft", 2.54, 1.27}, Dimensions{"wpa-8ft", 2.3368, 1.1684},
        Dimensions{"wpa-7ft", 1.9812, 0.9906}}) {
    SCOPED_TRACE(d.name);
    const auto spec = loadTableSpec(d.name);
    ASSERT_TRUE(spec) << spec.error();
    EXPECT_EQ(spec->name, d.name);
    EXPECT_DOUBLE_EQ(spec->length, d.length);
    EXPECT_DOUBLE_EQ(spec->width, d.width);
    EXPECT_DOUBLE_EQ(spec->corner.mouth, 0.1156);
    EXPECT_DOUBLE_EQ(spec->corner.jaw_angle_deg, 142.0);
    EXPECT_DOUBLE_EQ(spec->corner.hole_radius, 0.07);
    EXPECT_DOUBLE_EQ(spec->corner.hole_offset, 0.042);
    EXPECT_DOUBLE_EQ(spec->side.mouth, 0.1285);
    EXPECT_DOUBLE_EQ(spec->side.jaw_angle_deg, 104.0);
    EXPECT_DOUBLE_EQ(spec->side.hole_radius, 0.065);
    EXPECT_DOUBLE_EQ(spec->side.hole_offset, 0.075);
    EXPECT_TRUE(spec->collision_mesh.is_absolute());
    EXPECT_EQ(spec->collision_mesh.filename(), std::string(d.name) + ".obj");
    EXPECT_TRUE(fs::exists(spec->collision_mesh));
  }
}

TEST(TableSpec, ShippedCoefficientsAreTheDefaults) {
  const PhysicsParams defaults;
  for (const char* name : {"wpa-9ft", "wpa-8ft", "wpa-7ft"}) {
    SCOPED_TRACE(name);
    const auto spec = loadTableSpec(name);
    ASSERT_TRUE(spec) << spec.error();
    const PhysicsParams& p = spec->params;
    EXPECT_DOUBLE_EQ(p.u_s, defaults.u_s);
    EXPECT_DOUBLE_EQ(p.u_r, defaults.u_r);
    EXPECT_DOUBLE_EQ(p.spin_decel, defaults.spin_decel);
    EXPECT_DOUBLE_EQ(p.e_b, defaults.e_b);
    EXPECT_FALSE(p.u_b.has_value());
    EXPECT_DOUBLE_EQ(p.e_c, defaults.e_c);
    EXPECT_DOUBLE_EQ(p.u_c, defaults.u_c);
    EXPECT_DOUBLE_EQ(p.e_slate, defaults.e_slate);
    EXPECT_DOUBLE_EQ(p.cushion_height, defaults.cushion_height);
    EXPECT_DOUBLE_EQ(p.ball_mass, defaults.ball_mass);
    EXPECT_DOUBLE_EQ(p.ball_radius, defaults.ball_radius);
    EXPECT_DOUBLE_EQ(p.cue_mass, defaults.cue_mass);
    EXPECT_DOUBLE_EQ(p.cue_end_mass, defaults.cue_end_mass);
    EXPECT_DOUBLE_EQ(p.miscue_limit, defaults.miscue_limit);
  }
}

TEST(TableSpec, LoadsByPathAndResolvesMeshesBesideTheSpec) {
  TempDir dir;
  json j = shippedJson("wpa-8ft");
  j["collision_mesh"] = "meshes/custom.obj";
  j.erase("render_mesh");
  j["params"] = json{{"u_s", 0.3}, {"u_b", 0.05}};
  const auto spec = loadTableSpec(dir.write("my-table.json", j.dump()).string());
  ASSERT_TRUE(spec) << spec.error();
  EXPECT_EQ(spec->collision_mesh, (dir.path() / "meshes" / "custom.obj").lexically_normal());
  EXPECT_EQ(spec->render_mesh, spec->collision_mesh);
  EXPECT_DOUBLE_EQ(spec->params.u_s, 0.3);
  ASSERT_TRUE(spec->params.u_b.has_value());
  EXPECT_DOUBLE_EQ(*spec->params.u_b, 0.05);
  EXPECT_DOUBLE_EQ(spec->params.u_r, 0.01);  // untouched coefficients keep their defaults
}

TEST(TableSpec, ModelsNameTheContactModelOfEachPair) {
  TempDir dir;
  json j = shippedJson("wpa-9ft");
  const std::string other = ContactModels{}.ball_cushion == "han2005" ? "mathavan2010" : "han2005";
  j["models"] = json{{"ball_cushion", other}};
  const auto spec = loadTableSpec(dir.write("models.json", j.dump()).string());
  ASSERT_TRUE(spec) << spec.error();
  EXPECT_EQ(spec->models.ball_cushion, other);
  EXPECT_EQ(spec->models.ball_ball, "alciatore");  // pairs not named keep their default
  for (const auto pair : contactPairs()) EXPECT_FALSE(knownModels(pair).empty()) << pair;
}

TEST(TableSpec, NameDefaultsToTheFileStem) {
  TempDir dir;
  json j = shippedJson("wpa-7ft");
  j.erase("name");
  const auto spec = loadTableSpec(dir.write("garage.json", j.dump()).string());
  ASSERT_TRUE(spec) << spec.error();
  EXPECT_EQ(spec->name, "garage");
}

TEST(TableSpec, ParsesTextWithoutAFile) {
  json j = shippedJson("wpa-7ft");
  j.erase("name");
  j["collision_mesh"] = "meshes/t.obj";
  const auto spec = parseTableSpec(j.dump(), "inline", "/tables", "given");
  ASSERT_TRUE(spec) << spec.error();
  EXPECT_EQ(spec->name, "given");
  EXPECT_DOUBLE_EQ(spec->length, j["length"].get<double>());
  EXPECT_EQ(spec->collision_mesh, fs::path("/tables/meshes/t.obj"));

  const auto broken = parseTableSpec("{\"length\":", "inline", "/tables", "given");
  ASSERT_FALSE(broken);
  EXPECT_EQ(broken.error().rfind("inline: invalid JSON", 0), 0u) << broken.error();
}

TEST(TableSpec, BadFieldsGiveOneLineReasonsNamingTheField) {
  TempDir dir;
  struct Case {
    std::function<void(json&)> edit;
    std::string reason;
  };
  const std::vector<Case> cases{
      {[](json& j) { j["corner"].erase("mouth"); },
       "corner.mouth: missing (must be a finite number > 0)"},
      {[](json& j) { j["corner"]["mouth"] = "wide"; }, "corner.mouth: must be a finite number > 0"},
      {[](json& j) { j["corner"]["mouth"] = -0.1; }, "corner.mouth: must be a finite number > 0"},
      {[](json& j) { j["length"] = nullptr; }, "length: must be a finite number > 0"},
      {[](json& j) { j.erase("width"); }, "width: missing (must be a finite number > 0)"},
      {[](json& j) { j["side"]["jaw_angle_deg"] = 80; },
       "side.jaw_angle_deg: must be a finite number in (90, 180)"},
      {[](json& j) { j["side"]["hole_offset"] = true; },
       "side.hole_offset: must be a finite number"},
      {[](json& j) { j["slate_thickness"] = 0.2; },
       "slate_thickness: must be a finite number in (0, 0.05]"},
      {[](json& j) { j["side"] = 3; }, "side: must be an object"},
      {[](json& j) { j.erase("corner"); }, "corner: missing (must be an object)"},
      {[](json& j) { j["lenght"] = 2.5; }, "lenght: unknown field"},
      {[](json& j) { j["corner"]["radius"] = 2.5; }, "corner.radius: unknown field"},
      {[](json& j) { j["name"] = 5; }, "name: must be a string"},
      {[](json& j) { j["collision_mesh"] = json::array(); }, "collision_mesh: must be a string"},
      {[](json& j) { j["params"] = 1; }, "params: must be an object"},
      {[](json& j) { j["params"]["u_s"] = 5; }, "params.u_s: must be a finite number in (0, 2]"},
      {[](json& j) { j["params"]["u_s"] = "fast"; },
       "params.u_s: must be a finite number in (0, 2]"},
      {[](json& j) { j["params"]["e_c"] = nullptr; },
       "params.e_c: must be a finite number in [0, 1]"},
      {[](json& j) { j["params"]["mu"] = 0.2; }, "params.mu: unknown parameter"},
      {[](json& j) { j["params"]["cushion_height"] = 0.02; },
       "params.cushion_height: must be above ball_radius and below 2 * ball_radius"},
      {[](json& j) { j["models"] = 1; }, "models: must be an object"},
      {[](json& j) { j["models"]["ball_cushion"] = "bouncy"; },
       "models.ball_cushion: unknown model 'bouncy' (known: han2005, mathavan2010, "
       "stronge_compliant)"},
      {[](json& j) { j["models"]["ball_cushion"] = 2010; },
       "models.ball_cushion: must be a string"},
      {[](json& j) { j["models"]["ball_rail"] = "han2005"; },
       "models.ball_rail: unknown contact pair (known: ball_cloth, ball_ball, ball_cushion, "
       "ball_slate, cue_ball)"},
      {[](json& j) { j["length"] = 0.2; }, "length: too short for its pockets"},
      {[](json& j) { j["width"] = 0.1; }, "width: too narrow for its pockets"},
      {[](json& j) { j["corner"]["mouth"] = 0.05; },
       "corner.mouth: must be wider than a ball (2 * ball_radius)"},
      {[](json& j) { j["side"]["hole_radius"] = 0.02; },
       "side.hole_radius: must be larger than ball_radius"},
      {[](json& j) { j["corner"]["hole_radius"] = 0.13; },
       "corner.hole_radius: the hole reaches beyond the rail"},
      {[](json& j) {
         j["corner"]["hole_offset"] = -0.03;
         j["corner"]["hole_radius"] = 0.08;
       },
       "corner.hole_radius: the hole reaches the jaw points"},
  };
  for (const Case& c : cases) {
    EXPECT_EQ(reasonAfter(dir, c.edit), c.reason);
  }
}

TEST(TableSpec, FileLevelFailures) {
  TempDir dir;
  const auto unknown = loadTableSpec("wpa-10ft");
  ASSERT_FALSE(unknown);
  EXPECT_NE(unknown.error().find("unknown table 'wpa-10ft'"), std::string::npos) << unknown.error();

  const auto missing = loadTableSpec((dir.path() / "nope.json").string());
  ASSERT_FALSE(missing);
  EXPECT_NE(missing.error().find("cannot open"), std::string::npos) << missing.error();

  const auto broken = loadTableSpec(dir.write("broken.json", "{\"length\": 2.54,").string());
  ASSERT_FALSE(broken);
  EXPECT_NE(broken.error().find("invalid JSON"), std::string::npos) << broken.error();

  const auto array = loadTableSpec(dir.write("array.json", "[1, 2]").string());
  ASSERT_FALSE(array);
  EXPECT_NE(array.error().find("must be a JSON object"), std::string::npos) << array.error();

  for (const auto* r : {&unknown, &missing, &broken, &array}) {
    EXPECT_EQ(r->error().find('\n'), std::string::npos) << r->error();
  }
}

TEST(PhysicsParams, NamesFollowTheContract) {
  const std::vector<std::string_view> expected{
      "u_s",          "u_r",         "spin_decel",     "e_b",       "u_b",         "e_c",
      "u_c",          "e_slate",     "cushion_height", "ball_mass", "ball_radius", "cue_mass",
      "cue_end_mass", "miscue_limit"};
  EXPECT_EQ(paramNames(), expected);
}

TEST(PhysicsParams, SetParamAcceptsInRangeValues) {
  PhysicsParams p;
  EXPECT_TRUE(setParam(p, "u_s", 0.25).ok());
  EXPECT_DOUBLE_EQ(p.u_s, 0.25);
  EXPECT_TRUE(setParam(p, "u_s", 2.0).ok());  // closed upper end
  EXPECT_TRUE(setParam(p, "u_r", 1.0).ok());  // closed upper end
  EXPECT_EQ(setParam(p, "u_r", 0.0).error(),
            "must be a finite number in (0, 1]");  // would roll for ever
  EXPECT_TRUE(setParam(p, "u_b", 0.06).ok());
  ASSERT_TRUE(p.u_b.has_value());
  EXPECT_DOUBLE_EQ(*p.u_b, 0.06);
  EXPECT_TRUE(setParam(p, "cushion_height", 0.04).ok());
  EXPECT_DOUBLE_EQ(p.cushion_height, 0.04);
  EXPECT_TRUE(setParam(p, "miscue_limit", 1.0).ok());
}

TEST(PhysicsParams, SetParamRejectsAndLeavesValuesAlone) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  PhysicsParams p;
  EXPECT_EQ(setParam(p, "u_s", 0.0).error(), "must be a finite number in (0, 2]");
  EXPECT_EQ(setParam(p, "u_s", 2.5).error(), "must be a finite number in (0, 2]");
  EXPECT_EQ(setParam(p, "u_s", nan).error(), "must be a finite number in (0, 2]");
  EXPECT_EQ(setParam(p, "e_b", 1.01).error(), "must be a finite number in [0, 1]");
  EXPECT_EQ(setParam(p, "u_b", -0.1).error(), "must be a finite number in [0, 1]");
  EXPECT_EQ(setParam(p, "ball_mass", inf).error(), "must be a finite number in (0, 10]");
  EXPECT_EQ(setParam(p, "spin_decel", -1.0).error(), "must be a finite number in (0, 1000]");
  EXPECT_EQ(setParam(p, "miscue_limit", 0.0).error(), "must be a finite number in (0, 1]");
  EXPECT_EQ(setParam(p, "friction", 0.2).error(), "unknown parameter");
  const PhysicsParams defaults;
  EXPECT_DOUBLE_EQ(p.u_s, defaults.u_s);
  EXPECT_DOUBLE_EQ(p.e_b, defaults.e_b);
  EXPECT_FALSE(p.u_b.has_value());
  EXPECT_DOUBLE_EQ(p.ball_mass, defaults.ball_mass);
}

TEST(PhysicsParams, EveryNameAcceptsItsTypicalValue) {
  const PhysicsParams d;
  const std::vector<std::pair<std::string_view, double>> typical{
      {"u_s", d.u_s},
      {"u_r", d.u_r},
      {"spin_decel", d.spin_decel},
      {"e_b", d.e_b},
      {"u_b", 0.06},
      {"e_c", d.e_c},
      {"u_c", d.u_c},
      {"e_slate", d.e_slate},
      {"cushion_height", d.cushion_height},
      {"ball_mass", d.ball_mass},
      {"ball_radius", d.ball_radius},
      {"cue_mass", d.cue_mass},
      {"cue_end_mass", d.cue_end_mass},
      {"miscue_limit", d.miscue_limit}};
  ASSERT_EQ(typical.size(), paramNames().size());
  PhysicsParams p;
  for (const auto& [name, value] : typical) EXPECT_TRUE(setParam(p, name, value).ok()) << name;
  EXPECT_TRUE(validate(p).ok());
  EXPECT_TRUE(validate(PhysicsParams{}).ok());
}

TEST(PhysicsParams, ValidateChecksRangesAndConsistency) {
  PhysicsParams p;
  p.cushion_height = p.ball_radius;
  EXPECT_EQ(validate(p).error(),
            "cushion_height: must be above ball_radius and below 2 * ball_radius");
  p.cushion_height = 2.0 * p.ball_radius;
  EXPECT_EQ(validate(p).error(),
            "cushion_height: must be above ball_radius and below 2 * ball_radius");
  p.cushion_height = 1.5 * p.ball_radius;
  EXPECT_TRUE(validate(p).ok());

  PhysicsParams q;
  q.e_c = 1.5;
  EXPECT_EQ(validate(q).error(), "e_c: must be a finite number in [0, 1]");
  q = PhysicsParams{};
  q.u_b = 2.0;
  EXPECT_EQ(validate(q).error(), "u_b: must be a finite number in [0, 1]");
  q = PhysicsParams{};
  q.u_r = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(validate(q).error(), "u_r: must be a finite number in (0, 1]");
  q = PhysicsParams{};
  q.cue_end_mass = 1.0;
  EXPECT_EQ(validate(q).error(), "cue_end_mass: must not exceed cue_mass");
}

// Found by fuzz_table_spec: a key holding a newline (or any control character) is named in the
// refusal escaped, so the refusal stays one line (a log line nobody can forge).
TEST(TableSpec, AnUnknownKeyWithControlCharactersIsRefusedInOneLine) {
  for (const char* parent : {"", "params", "models", "corner"}) {
    json doc = shippedJson("wpa-8ft");
    json& where = std::string(parent).empty() ? doc : doc[parent];
    where["r\nder_mesh\x1B"] = std::string(parent) == "models" ? json("han2005") : json(1.0);
    const auto spec = parseTableSpec(doc.dump(), "fuzz.json", kTablesDir.string(), "fuzz");
    ASSERT_FALSE(spec) << parent;
    EXPECT_EQ(spec.error().find('\n'), std::string::npos) << spec.error();
    EXPECT_EQ(spec.error().find('\x1B'), std::string::npos) << spec.error();
    EXPECT_NE(spec.error().find("r\\x0Ader_mesh\\x1B"), std::string::npos) << spec.error();
  }
}

}  // namespace
}  // namespace pool::table
