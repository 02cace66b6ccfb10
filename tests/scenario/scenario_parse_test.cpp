// Scenario parsing: defaults, units, racks and overrides, params, a one-line reason per bad input.
#include <gtest/gtest.h>

#include <unistd.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "bad_scenarios.h"
#include "scenario/scenario.h"
#include "table/assets.h"
#include "table/rack.h"

namespace pool::scenario {
namespace {

using testing::goodScenario;
using testing::withRaw;
using testing::withRaws;

constexpr double kR = 0.028575;

Scenario parseOk(const std::string& text) {
  auto s = parseScenario(text);
  EXPECT_TRUE(s.hasValue()) << s.error();
  return s ? *s : Scenario{};
}

const physics::Ball* ballById(const Scenario& s, int id) {
  for (const auto& b : s.balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

TEST(ScenarioParse, DefaultsFollowTheContract) {
  const std::string text = R"({"balls": [{"id": 0, "x": -0.635, "y": 0}], "shot": {"speed": 2}})";
  const Scenario s = parseOk(text);
  EXPECT_EQ(s.spec.name, "wpa-9ft");
  EXPECT_DOUBLE_EQ(s.spec.length, 2.54);
  EXPECT_EQ(s.seed, 0u);
  EXPECT_DOUBLE_EQ(s.options.max_time, 60.0);
  EXPECT_DOUBLE_EQ(s.options.sample_hz, 0.0);
  EXPECT_FALSE(s.shot.speed_is_ball);
  EXPECT_DOUBLE_EQ(s.shot.yaw, 0.0);
  EXPECT_DOUBLE_EQ(s.shot.tip_side, 0.0);
  EXPECT_DOUBLE_EQ(s.shot.tip_height, 0.0);
  EXPECT_DOUBLE_EQ(s.shot.elevation, 0.0);
  EXPECT_DOUBLE_EQ(s.shot.speed, 2.0);
  EXPECT_DOUBLE_EQ(s.spec.params.u_s, 0.2);
}

TEST(ScenarioParse, DegreesBecomeRadians) {
  const Scenario s = parseOk(withRaws({{"/shot/yaw_deg", "90"}, {"/shot/elevation_deg", "30"}}));
  EXPECT_DOUBLE_EQ(s.shot.yaw, std::numbers::pi / 2);
  EXPECT_DOUBLE_EQ(s.shot.elevation, std::numbers::pi / 6);
}

TEST(ScenarioParse, ReadsEveryShotField) {
  const Scenario s = parseOk(withRaws({{"/shot/tip_side", "0.2"},
                                       {"/shot/tip_height", "-0.3"},
                                       {"/shot/speed", "4.5"},
                                       {"/shot/speed_is", "\"ball\""}}));
  EXPECT_DOUBLE_EQ(s.shot.tip_side, 0.2);
  EXPECT_DOUBLE_EQ(s.shot.tip_height, -0.3);
  EXPECT_DOUBLE_EQ(s.shot.speed, 4.5);
  EXPECT_TRUE(s.shot.speed_is_ball);
}

TEST(ScenarioParse, BallsAreAtRestOnTheSlateSortedById) {
  const Scenario s = parseOk(
      withRaws({{"/balls", R"([{"id": 5, "x": 0.5, "y": 0.1}, {"id": 0, "x": -0.6, "y": 0.2}])"}}));
  ASSERT_EQ(s.balls.size(), 2u);
  EXPECT_EQ(s.balls[0].id, 0);
  EXPECT_EQ(s.balls[1].id, 5);
  EXPECT_DOUBLE_EQ(s.balls[1].pos.x(), 0.5);
  EXPECT_DOUBLE_EQ(s.balls[1].pos.y(), 0.1);
  EXPECT_DOUBLE_EQ(s.balls[1].pos.z(), kR);
  EXPECT_EQ(s.balls[1].state, physics::MotionState::Stationary);
  EXPECT_TRUE(s.balls[1].vel.isZero());
}

TEST(ScenarioParse, EightBallRackPutsTheCueBallOnTheHeadSpot) {
  const Scenario s = parseOk(R"({"rack": "8ball", "shot": {"speed": 8}})");
  ASSERT_EQ(s.balls.size(), 16u);
  for (int id = 0; id <= 15; ++id) EXPECT_EQ(s.balls[static_cast<std::size_t>(id)].id, id);
  const auto spots = table::spotsFor(s.spec);
  EXPECT_DOUBLE_EQ(s.balls[0].pos.x(), spots.head_spot.x());
  EXPECT_DOUBLE_EQ(s.balls[0].pos.y(), spots.head_spot.y());
  // The apex ball sits on the foot spot.
  int on_foot_spot = 0;
  for (const auto& b : s.balls)
    on_foot_spot += (b.pos.head<2>() - spots.foot_spot).norm() < 1e-9 ? 1 : 0;
  EXPECT_EQ(on_foot_spot, 1);
}

TEST(ScenarioParse, NineBallRackHasTenBalls) {
  const Scenario s = parseOk(R"({"rack": "9ball", "shot": {"speed": 8}})");
  ASSERT_EQ(s.balls.size(), 10u);
  EXPECT_EQ(s.balls.back().id, 9);
}

TEST(ScenarioParse, RackFollowsTheSeedAndTheRackFunction) {
  for (std::uint64_t seed : {0u, 1u, 7u}) {
    const Scenario s =
        parseOk(R"({"rack": "8ball", "shot": {"speed": 8}, "seed": )" + std::to_string(seed) + "}");
    EXPECT_EQ(s.seed, seed);
    for (const auto& placed : table::rackBalls(table::RackType::EightBall, s.spec, kR, seed)) {
      const physics::Ball* b = ballById(s, placed.id);
      ASSERT_NE(b, nullptr);
      EXPECT_DOUBLE_EQ(b->pos.x(), placed.pos.x());
      EXPECT_DOUBLE_EQ(b->pos.y(), placed.pos.y());
    }
  }
}

TEST(ScenarioParse, HandRackGapsFollowTheSeed) {
  const Scenario s = parseOk(R"({"rack": "9ball", "rack_gaps": "hand", "seed": 5,
                                 "shot": {"speed": 8}})");
  EXPECT_EQ(s.rack_generator, table::RackGenerator::Hand);
  for (const auto& placed :
       table::rackFor(table::RackType::NineBall, s.spec, kR, 5, table::RackGenerator::Hand)) {
    const physics::Ball* b = ballById(s, placed.id);
    ASSERT_NE(b, nullptr);
    EXPECT_DOUBLE_EQ(b->pos.x(), placed.pos.x());
    EXPECT_DOUBLE_EQ(b->pos.y(), placed.pos.y());
  }
  EXPECT_EQ(parseOk(R"({"rack": "8ball", "shot": {"speed": 8}})").rack_generator,
            table::RackGenerator::Frozen);
  EXPECT_EQ(
      parseScenario(R"({"rack": "8ball", "rack_gaps": "loose", "shot": {"speed": 8}})").error(),
      "rack_gaps: must be \"frozen\" or \"hand\"");
}

TEST(ScenarioParse, BallsOverrideTheRack) {
  const Scenario s = parseOk(
      R"({"rack": "9ball", "balls": [{"id": 0, "x": -0.9, "y": 0.3}, {"id": 9, "x": 0.0, "y": -0.4},
          {"id": 12, "x": -0.2, "y": 0.4}], "shot": {"speed": 8}})");
  ASSERT_EQ(s.balls.size(), 11u);
  EXPECT_DOUBLE_EQ(ballById(s, 0)->pos.x(), -0.9);
  EXPECT_DOUBLE_EQ(ballById(s, 0)->pos.y(), 0.3);
  EXPECT_DOUBLE_EQ(ballById(s, 9)->pos.y(), -0.4);
  ASSERT_NE(ballById(s, 12), nullptr);
}

TEST(ScenarioParse, ParamsChangeTheSpec) {
  const Scenario s =
      parseOk(withRaw("/params", R"({"u_s": 0.3, "u_r": 0.012, "e_b": 0.93, "u_b": 0.05})"));
  EXPECT_DOUBLE_EQ(s.spec.params.u_s, 0.3);
  EXPECT_DOUBLE_EQ(s.spec.params.u_r, 0.012);
  EXPECT_DOUBLE_EQ(s.spec.params.e_b, 0.93);
  ASSERT_TRUE(s.spec.params.u_b.has_value());
  EXPECT_DOUBLE_EQ(*s.spec.params.u_b, 0.05);
}

TEST(ScenarioParse, ModelsOverrideTheSpecsChoice) {
  const Scenario plain = parseOk(goodScenario().dump());
  const std::string other =
      plain.spec.models.ball_cushion == "han2005" ? "mathavan2010" : "han2005";
  const Scenario s = parseOk(withRaw("/models", R"({"ball_cushion": ")" + other + R"("})"));
  EXPECT_EQ(s.spec.models.ball_cushion, other);
  EXPECT_EQ(s.spec.models.ball_ball, plain.spec.models.ball_ball);
}

TEST(ScenarioParse, EveryContractParamNameIsAccepted) {
  // SIM-CONTRACT.md's names, each with its typical value.
  const std::vector<std::pair<std::string, double>> contract = {{"u_s", 0.2},
                                                                {"u_r", 0.01},
                                                                {"spin_decel", 10.9},
                                                                {"e_b", 0.95},
                                                                {"u_b", 0.06},
                                                                {"e_c", 0.85},
                                                                {"u_c", 0.2},
                                                                {"e_slate", 0.5},
                                                                {"cushion_height", 0.03629},
                                                                {"ball_mass", 0.170097},
                                                                {"ball_radius", 0.028575},
                                                                {"cue_mass", 0.567},
                                                                {"cue_end_mass", 0.0085},
                                                                {"miscue_limit", 0.5}};
  std::vector<std::string> names(table::paramNames().begin(), table::paramNames().end());
  ASSERT_EQ(names.size(), contract.size());
  for (std::size_t i = 0; i < contract.size(); ++i) {
    EXPECT_EQ(names[i], contract[i].first);
    nlohmann::json params;
    params[contract[i].first] = contract[i].second;
    const auto s = parseScenario(withRaw("/params", params.dump()));
    EXPECT_TRUE(s.hasValue()) << contract[i].first << ": " << s.error();
  }
}

TEST(ScenarioParse, BallRadiusParamSetsTheRestHeight) {
  const double r = 0.0286;
  const Scenario s =
      parseOk(withRaw("/params", R"({"ball_radius": 0.0286, "cushion_height": 0.0363})"));
  EXPECT_DOUBLE_EQ(s.spec.params.ball_radius, r);
  for (const auto& b : s.balls) EXPECT_DOUBLE_EQ(b.pos.z(), r);
}

TEST(ScenarioParse, OtherTableSizes) {
  EXPECT_DOUBLE_EQ(parseOk(withRaw("/table", "\"wpa-8ft\"")).spec.length, 2.3368);
  EXPECT_DOUBLE_EQ(parseOk(withRaw("/table", "\"wpa-7ft\"")).spec.width, 0.9906);
}

TEST(ScenarioParse, OptionsAreRead) {
  const Scenario s =
      parseOk(withRaws({{"/seed", "42"}, {"/max_time", "12.5"}, {"/trajectory_hz", "30"}}));
  EXPECT_EQ(s.seed, 42u);
  EXPECT_DOUBLE_EQ(s.options.max_time, 12.5);
  EXPECT_DOUBLE_EQ(s.options.sample_hz, 30.0);
}

TEST(ScenarioParse, EdgeValuesAreLegal) {
  for (const auto& [name, text] : testing::edgeScenarios()) {
    const auto s = parseScenario(text);
    EXPECT_TRUE(s.hasValue()) << name << ": " << s.error();
  }
}

TEST(ScenarioParse, BadInputGivesOneLineNamingTheField) {
  for (const auto& bad : testing::badScenarios()) {
    const auto s = parseScenario(bad.text);
    ASSERT_FALSE(s.hasValue()) << bad.name;
    EXPECT_EQ(s.error().rfind(bad.reason, 0), 0u) << bad.name << ": got \"" << s.error() << "\"";
    EXPECT_EQ(s.error().find('\n'), std::string::npos) << bad.name;
    EXPECT_LT(s.error().size(), 300u) << bad.name;
  }
}

TEST(ScenarioParse, UnknownFieldReasonListsTheKnownOnes) {
  const auto s = parseScenario(withRaw("/shot/sped", "2"));
  ASSERT_FALSE(s.hasValue());
  EXPECT_EQ(s.error(),
            "shot.sped: unknown field (expected one of yaw_deg, tip_side, tip_height, "
            "elevation_deg, speed, speed_is)");
}

TEST(ScenarioParse, ExactReasonsForCommonMistakes) {
  EXPECT_EQ(parseScenario(withRaw("/shot/speed", "13")).error(),
            "shot.speed: must be in (0, 12] m/s");
  EXPECT_EQ(parseScenario(withRaw("/shot/speed", "1e999")).error(),
            "shot.speed: must be a finite number, got 1e999");
  EXPECT_EQ(parseScenario(withRaw("/shot/speed", "\"2\"")).error(),
            "shot.speed: must be a number, got \"2\"");
  EXPECT_EQ(parseScenario(withRaw("/params", R"({"mu_s": 0.2})")).error(),
            "params.mu_s: unknown parameter");
  EXPECT_EQ(parseScenario("").error(), "scenario: empty input");
}

TEST(ScenarioParse, ParamsUnknownNameIsReportedBeforeItsType) {
  EXPECT_EQ(parseScenario(withRaw("/params", R"({"gravity": "x"})")).error(),
            "params.gravity: unknown parameter");
}

// A scene file refers to a table spec beside it by a relative path, whatever the working directory.
TEST(ScenarioLoad, RelativeTablePathIsFoundBesideTheScenario) {
  const auto spec_path = table::findAsset("tables/wpa-8ft.json");
  ASSERT_TRUE(spec_path.has_value());
  const auto dir =
      std::filesystem::temp_directory_path() / ("pool_scenario_load_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  std::filesystem::copy_file(*spec_path, dir / "my_table.json",
                             std::filesystem::copy_options::overwrite_existing);
  std::ofstream(dir / "scene.json") << withRaw("/table", "\"my_table.json\"");
  const auto s = loadScenario((dir / "scene.json").string());
  std::filesystem::remove_all(dir);
  ASSERT_TRUE(s.hasValue()) << s.error();
  EXPECT_DOUBLE_EQ(s->spec.length, 2.3368);
}

TEST(ScenarioLoad, BareNameFindsASharedScene) {
  const auto s = loadScenario("break");
  ASSERT_TRUE(s.hasValue()) << s.error();
  EXPECT_EQ(s->balls.size(), 16u);
}

TEST(ScenarioLoad, MissingFilesAndScenesFailWithOneLine) {
  const auto missing = loadScenario("/nonexistent/scene.json");
  ASSERT_FALSE(missing.hasValue());
  EXPECT_EQ(missing.error().rfind("scenario: cannot read '/nonexistent/scene.json'", 0), 0u)
      << missing.error();
  const auto no_scene = loadScenario("no_such_scene");
  ASSERT_FALSE(no_scene.hasValue());
  EXPECT_EQ(no_scene.error().rfind("scenario: ", 0), 0u);
  const auto dir = loadScenario("/tmp");
  ASSERT_FALSE(dir.hasValue());
  EXPECT_NE(dir.error().find("is a directory"), std::string::npos) << dir.error();
}

}  // namespace
}  // namespace pool::scenario
