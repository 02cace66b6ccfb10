// A stored shot's scenario file: its name, its content and its writing.
#include "client/ui/shot_export.h"

#include <fstream>
#include <system_error>

namespace pool::ui {

scenario::ScenarioSource shotScenario(const protocol::HistoryShot& shot) {
  scenario::ScenarioSource source;
  source.table = shot.table;
  source.balls = shot.before;
  source.shot = shot.cue;
  return source;
}

std::string scenarioFileName(const std::string& match, std::uint32_t shot) {
  std::string name;
  for (const char c : match) {
    const bool plain = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                       c == '-' || c == '_';
    name += plain ? c : '_';
  }
  return name + "-shot-" + std::to_string(shot) + ".json";
}

Result<std::filesystem::path> exportShot(const protocol::HistoryShot& shot,
                                         const std::filesystem::path& dir) {
  using Written = Result<std::filesystem::path>;
  if (!shot.found) return Written::fail("no shot to export");
  if (!shot.shoots) {
    return Written::fail("shot " + std::to_string(shot.shot_number) +
                         " re-racked the table: no stroke to export");
  }
  if (shot.cue.ball != physics::kCueBall) {
    // Three-cushion's second player strikes their own ball; a scenario file strikes the cue ball.
    return Written::fail("shot " + std::to_string(shot.shot_number) + " struck ball " +
                         std::to_string(shot.cue.ball) +
                         ": a scenario file strikes the cue ball only");
  }
  std::error_code error;
  std::filesystem::path path = std::filesystem::absolute(dir, error);
  if (error) return Written::fail("cannot export: " + error.message());
  path /= scenarioFileName(shot.match, shot.shot_number);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (out) out << scenario::scenarioJson(shotScenario(shot));
  out.close();
  if (!out) return Written::fail("cannot write " + path.string());
  return Written::ok(path.lexically_normal());
}

}  // namespace pool::ui
