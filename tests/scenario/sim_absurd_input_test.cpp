// pool-sim refuses what no scenario can be: a device as the table or the scenario (/dev/zero would
// be read without end) and a heading of 1e308 degrees, each with exit 2 and one line on stderr.
#include <gtest/gtest.h>

#include <string>

#include "process_runner.h"

namespace pool::scenario {
namespace {

using testing::ProcessResult;
using testing::runProcess;

const std::string kSim = std::string(POOL_BIN_DIR) + "/pool-sim";

/// The break scene with `table` and `yaw` in place of its own.
std::string breakWith(const std::string& table, const std::string& yaw) {
  return R"({"table": ")" + table + R"(", "rack": "8ball", "shot": {"yaw_deg": )" + yaw +
         R"(, "speed": 8.0}})";
}

void expectRefused(const ProcessResult& r, const std::string& reason, const std::string& what) {
  EXPECT_EQ(r.exit_code, 2) << what << ": " << r.err;
  EXPECT_EQ(r.out, "") << what;
  ASSERT_FALSE(r.err.empty()) << what;
  EXPECT_EQ(r.err.find('\n'), r.err.size() - 1) << what << ": " << r.err;
  EXPECT_NE(r.err.find(reason), std::string::npos) << what << ": got \"" << r.err << "\"";
}

TEST(SimAbsurdInput, ADeviceAsTheTableIsRefused) {
  expectRefused(runProcess({kSim, "-"}, breakWith("/dev/zero", "0.0")), "not a regular file",
                "table /dev/zero");
}

TEST(SimAbsurdInput, ADeviceAsTheScenarioIsRefused) {
  expectRefused(runProcess({kSim, "/dev/zero"}), "not a regular file", "scenario /dev/zero");
}

TEST(SimAbsurdInput, AHeadingPastATurnIsRefused) {
  expectRefused(runProcess({kSim, "-"}, breakWith("wpa-9ft", "1e308")), "yaw_deg", "yaw_deg 1e308");
  expectRefused(runProcess({kSim, "-"}, breakWith("wpa-9ft", "-3601")), "yaw_deg", "yaw_deg -3601");
  // Ten turns either way are still a heading.
  EXPECT_EQ(runProcess({kSim, "-"}, breakWith("wpa-9ft", "3600")).exit_code, 0);
}

}  // namespace
}  // namespace pool::scenario
