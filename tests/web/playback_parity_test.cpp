// The page plays frames back exactly as the window does: the same frames, arriving late, early,
// out of order and across two shots, given to the window's app::PlaybackClock and to the page's
// playback.js (run by Node) give the same play time, positions, orientations and motion flag.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "client/app/playback_clock.h"
#include "core/split_mix64.h"
#include "support/child_process.h"
#include "support/display_check.h"

namespace pool::client::test {
namespace {

using nlohmann::json;

std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

/// Two balls rolling and turning about tilted axes, frame k of `shot` (60 Hz).
TableFrame frameOf(std::uint32_t shot, std::uint32_t k) {
  TableFrame f;
  f.match = "srv-1";
  f.shot_number = shot;
  f.frame = k;
  f.sim_time = k / 60.0;
  for (int id : {0, 9}) {
    physics::Ball b;
    b.id = id;
    const double t = f.sim_time;
    b.pos = physics::Vec3(-0.5 + 0.8 * t + 0.1 * id, 0.2 * std::sin(3 * t + id), 0.028575);
    b.orient = physics::Quat(
        Eigen::AngleAxisd(9.0 * t * (id ? -1 : 1), physics::Vec3(0.3, 1.0, 0.1 * id).normalized()));
    f.balls.push_back(b);
  }
  return f;
}

json ballJson(const physics::Ball& b) {
  return json::array({b.id, b.pos.x(), b.pos.y(), b.pos.z(), b.orient.w(), b.orient.x(),
                      b.orient.y(), b.orient.z(), 1});
}

TEST(PlaybackParityTest, ThePageAndTheWindowDrawTheSameBallsAtTheSameTimes) {
  if (::access("/usr/bin/node", X_OK) != 0) POOL_NO_DISPLAY("no node to run the page's code");
  ScratchDir scratch("web-playback");
  SplitMix64 random(7);
  const auto jitter = [&] { return 0.03 * random.uniform(); };  // 0–30 ms late

  // The steps: frames arriving (some late, some out of order, one lost burst, a second shot), and
  // samples at 75 Hz, the way a window or a page draws.
  json steps = json::array();
  std::vector<std::pair<double, std::optional<TableFrame>>> timeline;
  for (std::uint32_t shot : {4u, 5u}) {
    const double start = shot == 4 ? 1.0 : 4.0;
    for (std::uint32_t k = 0; k < 120; ++k) {
      if (shot == 4 && k >= 40 && k < 52) continue;                 // a lost burst (a 0.2 s gap)
      const double late = (shot == 5 && k == 30) ? 0.7 : jitter();  // one far behind the rest
      timeline.emplace_back(start + k / 60.0 + late, frameOf(shot, k));
    }
  }
  for (int i = 0; i < 560; ++i) timeline.emplace_back(0.9 + i / 75.0, std::nullopt);
  std::stable_sort(timeline.begin(), timeline.end(),
                   [](const auto& a, const auto& b) { return a.first < b.first; });

  app::PlaybackClock window;
  std::vector<json> expected;
  for (const auto& [now, frame] : timeline) {
    if (frame) {
      json balls = json::array();
      for (const auto& b : frame->balls) balls.push_back(ballJson(b));
      steps.push_back({{"now", now},
                       {"frame",
                        {{"shot", frame->shot_number},
                         {"frame", frame->frame},
                         {"t", frame->sim_time},
                         {"balls", balls}}}});
      window.push(*frame, now);
    } else {
      const std::uint32_t settled = now < 3.5 ? 3 : now < 6.5 ? 4 : 5;
      steps.push_back({{"now", now}, {"settled", settled}});
      const auto balls = window.sample(now);
      json drawn = nullptr;
      if (balls) {
        drawn = json::array();
        for (const auto& b : *balls) drawn.push_back(ballJson(b));
      }
      expected.push_back(
          {{"play", window.playTime()}, {"balls", drawn}, {"inMotion", window.inMotion(settled)}});
    }
  }
  std::ofstream(scratch.file("steps.json")) << steps.dump();

  const std::string command = "/usr/bin/node '" + std::string(POOL_SOURCE_DIR) +
                              "/tests/web/playback_parity.mjs' '" + POOL_BIN_DIR +
                              "/../web/playback.js' '" + scratch.file("steps.json") + "' > '" +
                              scratch.file("page.json") + "' 2> '" + scratch.file("node.err") + "'";
  ASSERT_EQ(std::system(command.c_str()), 0) << readText(scratch.file("node.err"));
  const json page = json::parse(readText(scratch.file("page.json")));
  ASSERT_EQ(page.size(), expected.size());

  int drawn = 0, moving = 0;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    const json& w = expected[i];
    const json& p = page[i];
    ASSERT_NEAR(p["play"].get<double>(), w["play"].get<double>(), 1e-9) << "sample " << i;
    ASSERT_EQ(p["inMotion"], w["inMotion"]) << "sample " << i;
    ASSERT_EQ(p["balls"].is_null(), w["balls"].is_null()) << "sample " << i;
    if (w["balls"].is_null()) continue;
    ++drawn;
    moving += w["inMotion"].get<bool>() ? 1 : 0;
    ASSERT_EQ(p["balls"].size(), w["balls"].size());
    for (std::size_t b = 0; b < w["balls"].size(); ++b) {
      for (std::size_t c = 0; c < 8; ++c) {
        ASSERT_NEAR(p["balls"][b][c].get<double>(), w["balls"][b][c].get<double>(), 1e-9)
            << "sample " << i << ", ball " << b << ", field " << c;
      }
    }
  }
  // The run covers both shots drawn in motion and at rest.
  EXPECT_GT(drawn, 300);
  EXPECT_GT(moving, 100);
  EXPECT_LT(moving, drawn);
}

}  // namespace
}  // namespace pool::client::test
