// pool-sim as a user runs it: exit codes, one stderr line per failure, stdin, plots, determinism.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "bad_scenarios.h"
#include "process_runner.h"
#include "scenario/scenario.h"
#include "svg_check.h"

namespace pool::scenario {
namespace {

namespace fs = std::filesystem;
using testing::ProcessResult;
using testing::runProcess;

const std::string kSim = std::string(POOL_BIN_DIR) + "/pool-sim";
const std::string kBreak = std::string(POOL_SOURCE_DIR) + "/assets/scenes/break.json";

// A scratch folder under /tmp for one test, removed at the end.
class TempDir {
 public:
  TempDir()
      : path_(fs::temp_directory_path() /
              ("pool_sim_cli_" + std::to_string(::getpid()) + "_" + std::to_string(counter()++))) {
    fs::create_directories(path_);
  }
  ~TempDir() { fs::remove_all(path_); }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  std::string file(const std::string& name, const std::string& content) const {
    std::ofstream(path_ / name, std::ios::binary) << content;
    return (path_ / name).string();
  }
  std::string operator/(const std::string& name) const { return (path_ / name).string(); }

 private:
  static int& counter() {
    static int n = 0;
    return n;
  }
  fs::path path_;
};

std::string readFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// A failure as the contract wants it: exit 2, nothing on stdout, exactly one line on stderr.
void expectOneLineFailure(const ProcessResult& r, const std::string& reason_prefix,
                          const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
  EXPECT_EQ(r.out, "") << what;
  ASSERT_FALSE(r.err.empty()) << what;
  EXPECT_EQ(r.err.back(), '\n') << what;
  EXPECT_EQ(testing::countOf(r.err, "\n"), 1u) << what << ": " << r.err;
  EXPECT_EQ(r.err.rfind(reason_prefix, 0), 0u) << what << ": got \"" << r.err << "\"";
}

void expectSuccess(const ProcessResult& r, const std::string& what) {
  EXPECT_EQ(r.exit_code, 0) << what << ": " << r.err;
  EXPECT_EQ(r.err, "") << what;
  ASSERT_FALSE(r.out.empty()) << what;
  const auto j = nlohmann::json::parse(r.out, nullptr, false);
  ASSERT_FALSE(j.is_discarded()) << what;
  EXPECT_EQ(j["version"], 1) << what;
}

TEST(PoolSimCli, BadScenariosOnStdinExitTwoWithOneLine) {
  for (const auto& bad : testing::badScenarios()) {
    expectOneLineFailure(runProcess({kSim, "-"}, bad.text), bad.reason, bad.name);
  }
}

TEST(PoolSimCli, BadScenarioFilesExitTwoWithOneLine) {
  TempDir dir;
  for (const auto& bad : testing::badScenarios()) {
    const std::string path = dir.file(bad.name + ".json", bad.text);
    expectOneLineFailure(runProcess({kSim, path}), bad.reason, bad.name);
  }
}

TEST(PoolSimCli, EdgeValuesRun) {
  for (const auto& [name, text] : testing::edgeScenarios()) {
    expectSuccess(runProcess({kSim, "-"}, text), name);
  }
}

TEST(PoolSimCli, TruncatedFileOnDisk) {
  TempDir dir;
  const std::string text = readFile(kBreak);
  const std::string path = dir.file("cut.json", text.substr(0, text.size() / 2));
  expectOneLineFailure(runProcess({kSim, path}), "scenario: invalid JSON", "truncated break.json");
}

TEST(PoolSimCli, UnreadableInputs) {
  expectOneLineFailure(runProcess({kSim, "/nonexistent/scene.json"}),
                       "scenario: cannot read '/nonexistent/scene.json'", "missing file");
  expectOneLineFailure(runProcess({kSim, "/tmp"}), "scenario: cannot read '/tmp': is a directory",
                       "directory");
  expectOneLineFailure(runProcess({kSim, "no_such_scene"}), "scenario: ", "unknown scene name");
  if (::geteuid() != 0) {  // root reads everything
    TempDir dir;
    const std::string path = dir.file("locked.json", testing::goodScenario().dump());
    fs::permissions(path, fs::perms::none);
    expectOneLineFailure(runProcess({kSim, path}), "scenario: cannot read", "unreadable file");
  }
}

TEST(PoolSimCli, BadCommandLinesExitTwoWithOneLine) {
  const std::vector<std::vector<std::string>> lines = {{kSim},
                                                       {kSim, kBreak, "extra.json"},
                                                       {kSim, kBreak, "--plot"},
                                                       {kSim, "--frobnicate", kBreak},
                                                       {kSim, "-x"}};
  for (const auto& argv : lines) {
    std::string what;
    for (const auto& a : argv) what += a + " ";
    const ProcessResult r = runProcess(argv);
    EXPECT_EQ(r.exit_code, 2) << what;
    EXPECT_EQ(r.out, "") << what;
    EXPECT_EQ(testing::countOf(r.err, "\n"), 1u) << what << ": " << r.err;
    EXPECT_NE(r.err.find("usage: pool-sim"), std::string::npos) << what << ": " << r.err;
  }
}

TEST(PoolSimCli, HelpGoesToStdout) {
  const ProcessResult r = runProcess({kSim, "--help"});
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_EQ(r.err, "");
  EXPECT_NE(r.out.find("--plot"), std::string::npos);
}

TEST(PoolSimCli, BreakRunsFromAnotherDirectory) {
  const ProcessResult r = runProcess({kSim, kBreak}, "", "/");
  expectSuccess(r, "break");
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["balls"].size(), 16u);
  EXPECT_FALSE(j.contains("trajectory"));
  EXPECT_EQ(j["events"][0]["type"], "strike");
}

TEST(PoolSimCli, SameScenarioSameBytes) {
  const ProcessResult a = runProcess({kSim, kBreak});
  const ProcessResult b = runProcess({kSim, kBreak});
  expectSuccess(a, "first run");
  EXPECT_EQ(a.out, b.out);
}

TEST(PoolSimCli, StdinFileAndSceneNameAgree) {
  const ProcessResult by_path = runProcess({kSim, kBreak});
  const ProcessResult by_stdin = runProcess({kSim, "-"}, readFile(kBreak));
  const ProcessResult by_name = runProcess({kSim, "break"});
  expectSuccess(by_stdin, "stdin");
  EXPECT_EQ(by_path.out, by_stdin.out);
  EXPECT_EQ(by_path.out, by_name.out);
}

TEST(PoolSimCli, TrajectoryWhenAsked) {
  const ProcessResult r = runProcess({kSim, "-"}, testing::withRaw("/trajectory_hz", "10"));
  expectSuccess(r, "trajectory");
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("trajectory"));
  ASSERT_FALSE(j["trajectory"].empty());
  for (std::size_t k = 0; k < j["trajectory"].size(); ++k) {
    EXPECT_EQ(j["trajectory"][k]["t"].get<double>(), static_cast<double>(k) / 10.0);
    EXPECT_EQ(j["trajectory"][k]["balls"].size(), 2u);
  }
  EXPECT_LE(j["trajectory"].back()["t"].get<double>(), j["t_rest"].get<double>());
}

TEST(PoolSimCli, PlotIsAnSvgWithEveryPocketAndAPathPerMovingBall) {
  TempDir dir;
  const std::string svg_path = dir / "break.svg";
  const ProcessResult with_plot = runProcess({kSim, kBreak, "--plot", svg_path});
  expectSuccess(with_plot, "plot");
  // The JSON is the same with or without a plot (no trajectory added).
  EXPECT_EQ(with_plot.out, runProcess({kSim, kBreak}).out);

  const std::string svg = readFile(svg_path);
  EXPECT_EQ(svg.rfind("<svg", 0), 0u);
  EXPECT_NE(svg.find("</svg>"), std::string::npos);
  EXPECT_EQ(testing::tagBalance(svg), "");
  EXPECT_EQ(testing::countOf(svg, "class=\"pocket\""), 6u);

  // A ball moved if it ended elsewhere or left the table.
  const auto scene = loadScenario(kBreak);
  ASSERT_TRUE(scene.hasValue()) << scene.error();
  const auto result = nlohmann::json::parse(with_plot.out);
  std::size_t moved = 0;
  for (std::size_t i = 0; i < scene->balls.size(); ++i) {
    const auto& end = result["balls"][i];
    const auto& start = scene->balls[i];
    const double shift =
        std::hypot(end["x"].get<double>() - start.pos.x(), end["y"].get<double>() - start.pos.y());
    if (shift > 0.001 || end["state"] != "stationary") ++moved;
  }
  EXPECT_GT(moved, 1u);
  EXPECT_EQ(testing::countOf(svg, "class=\"path\""), moved);
  EXPECT_EQ(readFile(svg_path), svg);
}

TEST(PoolSimCli, PlotIsByteIdenticalAcrossRuns) {
  TempDir dir;
  runProcess({kSim, kBreak, "--plot", dir / "a.svg"});
  runProcess({kSim, kBreak, "--plot", dir / "b.svg"});
  EXPECT_EQ(readFile(dir / "a.svg"), readFile(dir / "b.svg"));
}

TEST(PoolSimCli, RelativePlotPathIsInTheWorkingDirectory) {
  TempDir dir;
  expectSuccess(runProcess({kSim, kBreak, "--plot", "rel.svg"}, "", dir / ""), "relative plot");
  EXPECT_EQ(readFile(dir / "rel.svg").rfind("<svg", 0), 0u);
}

TEST(PoolSimCli, UnwritablePlotPathExitsTwoWithOneLine) {
  expectOneLineFailure(runProcess({kSim, kBreak, "--plot", "/nonexistent/dir/out.svg"}),
                       "plot: cannot write", "missing folder");
  expectOneLineFailure(runProcess({kSim, kBreak, "--plot", "/tmp"}), "plot: cannot write",
                       "a directory");
  expectOneLineFailure(runProcess({kSim, kBreak, "--plot", ""}),
                       "plot: cannot write '': empty path", "empty path");
}

}  // namespace
}  // namespace pool::scenario
