// pool-sim: runs one scenario (SIM-CONTRACT.md), prints the result JSON, optionally plots as SVG.
#include <CLI/CLI.hpp>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <fstream>
#include <iostream>
#include <iterator>
#include <string>

#include "scenario/json_document.h"
#include "scenario/scenario.h"
#include "server/sim/stored_shot.h"

namespace {

using pool::Result;
namespace sc = pool::scenario;

constexpr int kOk = 0;
constexpr int kInternalError = 1;
constexpr int kBadInput = 2;
constexpr const char* kUsage =
    "usage: pool-sim SCENARIO.json|- [--plot OUT.svg] | pool-sim --db PATH --match ID --shot N";

struct Args {
  std::string scenario;
  std::string plot;
  bool plot_given = false;
  std::string db;  ///< with match and shot: a stored shot instead of a scenario file
  std::string match;
  std::uint32_t shot = 0;
};

// Prints one line on stderr and returns the exit code.
int failWith(const std::string& reason, int code = kBadInput) {
  std::fprintf(stderr, "%s\n", sc::oneLine(reason).c_str());
  return code;
}

Result<sc::Scenario> readScenario(const std::string& arg) {
  if (arg != "-") return sc::loadScenario(arg);
  std::string text((std::istreambuf_iterator<char>(std::cin)), std::istreambuf_iterator<char>());
  if (std::cin.bad()) return Result<sc::Scenario>::fail("scenario: cannot read standard input");
  return sc::parseScenario(text);
}

// The plot file, written before anything goes to stdout so that a failure leaves stdout empty.
std::string writePlot(const sc::Scenario& scenario, const pool::physics::ShotOutcome& outcome,
                      const std::string& path) {
  if (path.empty()) return "plot: cannot write '': empty path";
  auto plotted = sc::runForPlot(scenario, outcome);
  if (!plotted) return plotted.error();
  const std::string svg = sc::plotSvg(scenario, *plotted);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (out) out.write(svg.data(), static_cast<std::streamsize>(svg.size()));
  if (!out) return "plot: cannot write '" + path + "': " + std::strerror(errno);
  out.close();
  return out ? "" : "plot: cannot write '" + path + "'";
}

int run(const Args& args) {
  auto scenario = args.db.empty() ? readScenario(args.scenario)
                                  : pool::sim::storedShotScenario(args.db, args.match, args.shot);
  if (!scenario) return failWith(scenario.error());
  auto outcome = sc::runScenario(*scenario);
  if (!outcome) return failWith(outcome.error());
  const std::string json = sc::resultJson(*scenario, *outcome);
  if (args.plot_given) {
    if (const std::string why = writePlot(*scenario, *outcome, args.plot); !why.empty())
      return failWith(why);
  }
  std::fwrite(json.data(), 1, json.size(), stdout);
  if (std::fflush(stdout) != 0) return failWith("stdout: write failed", kInternalError);
  return kOk;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"pool-sim: runs one shot of the physics lab (docs/SIM-CONTRACT.md)", "pool-sim"};
  Args args;
  auto* scenario = app.add_option("scenario", args.scenario,
                                  "scenario file, scene name (e.g. break), or - for stdin");
  auto* plot =
      app.add_option("--plot", args.plot, "also write a top-down SVG of the table and every path");
  auto* db = app.add_option("--db", args.db, "a pool-server database: run one of its stored shots");
  auto* match = app.add_option("--match", args.match, "the stored shot's match id (with --db)");
  auto* shot = app.add_option("--shot", args.shot, "the stored shot's number, from 1 (with --db)");
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();
    return kOk;
  } catch (const CLI::ParseError& e) {
    return failWith(std::string(e.what()) + "; " + kUsage);
  }
  args.plot_given = plot->count() > 0;
  // Either a scenario, or a stored shot named by all three of --db, --match and --shot.
  const std::size_t stored = db->count() + match->count() + shot->count();
  if ((scenario->count() == 0) == (stored == 0) || (stored != 0 && stored != 3)) {
    return failWith(std::string(scenario->count() == 0 && stored == 0
                                    ? "scenario is required"
                                    : "a scenario, or all of --db, --match and --shot") +
                    "; " + kUsage);
  }
  try {
    return run(args);
  } catch (const std::exception& e) {
    return failWith(std::string("internal error: ") + e.what(), kInternalError);
  }
}
