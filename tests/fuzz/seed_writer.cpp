// Writes the fuzz seeds that exist only as code: ShotCommands serialized as they travel, and the
// scenario tests' refused and edge inputs. Usage: fuzz-seeds OUT_DIR (fills OUT_DIR/<target>/).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "net/convert.h"
#include "scenario/bad_scenarios.h"
#include "shot_command_cdr.h"

namespace {

namespace fs = std::filesystem;
using pool::protocol::ShotOption;
using pool::protocol::ShotRequest;

void writeFile(const fs::path& path, const void* data, std::size_t size) {
  std::ofstream(path, std::ios::binary)
      .write(static_cast<const char*>(data), static_cast<std::streamsize>(size));
}

/// Commands covering every optional part: a call, a placement, a choice without a shot, a
/// signature.
std::vector<ShotRequest> commands() {
  ShotRequest plain;
  plain.match = "srv-1";
  plain.seat = 1;
  plain.seat_token = 0x0123456789abcdefULL;
  plain.seq = 7;
  plain.cue = {0.3, 0.1, 0.2, 0.1, 3.0, false};
  ShotRequest called = plain;
  called.called_ball = 8;
  called.called_pocket = "foot_right_corner";
  ShotRequest placed = plain;
  placed.cue_ball_at = Eigen::Vector2d(-0.9, 0.2);
  placed.option = ShotOption::BallInHand;
  placed.safety = true;
  ShotRequest rebreak = plain;
  rebreak.option = ShotOption::OpponentReBreaks;
  ShotRequest signed_one = called;
  signed_one.signature.assign(64, 0xa5);
  return {plain, called, placed, rebreak, signed_one};
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: fuzz-seeds OUT_DIR\n");
    return 2;
  }
  const fs::path out(argv[1]);
  fs::create_directories(out / "shot_command_cdr");
  int n = 0;
  for (const ShotRequest& request : commands()) {
    const auto bytes = pool::fuzz::encodeShotCommand(*pool::net::toWire(request));
    writeFile(out / "shot_command_cdr" / ("command" + std::to_string(n++) + ".cdr"), bytes.data(),
              bytes.size());
  }
  fs::create_directories(out / "scenario");
  for (const auto& bad : pool::scenario::testing::badScenarios()) {
    writeFile(out / "scenario" / ("bad_" + bad.name + ".json"), bad.text.data(), bad.text.size());
  }
  for (const auto& [name, text] : pool::scenario::testing::edgeScenarios()) {
    writeFile(out / "scenario" / ("edge_" + name + ".json"), text.data(), text.size());
  }
  return 0;
}
