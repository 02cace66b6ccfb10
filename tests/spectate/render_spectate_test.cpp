// pool-client --spectate any --screenshot, following a bot match through EGL (no display): every
// ball is drawn where the server's layout puts it, checked by projecting each ball with the
// camera the client drew with and looking at the PNG's pixels there.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>

#include "client/render/renderer.h"
#include "support/client_fixture.h"
#include "support/png_image.h"

namespace pool::client::test {
namespace {

class RenderSpectateTest : public ClientIntegrationTest {};

glm::vec3 vec3Of(const nlohmann::json& a) {
  return {a.at(0).get<float>(), a.at(1).get<float>(), a.at(2).get<float>()};
}

/// True when every on-table ball of `drawn` lies where some layout the server published put it.
bool matchesALayout(const nlohmann::json& drawn, const std::vector<MatchView>& layouts) {
  for (const MatchView& view : layouts) {
    bool all = true;
    for (const auto& d : drawn) {
      if (d.at("pocketed").get<bool>()) continue;
      bool found = false;
      for (const auto& b : view.balls) {
        if (b.id != d.at("id").get<int>() || !physics::onTable(b.state)) continue;
        const glm::vec3 p = vec3Of(d.at("pos"));
        found = std::abs(p.x - b.pos.x()) < 1e-5 && std::abs(p.y - b.pos.y()) < 1e-5;
      }
      all = all && found;
    }
    if (all) return true;
  }
  return false;
}

TEST_F(RenderSpectateTest, ASpectatorsScreenshotDrawsEachBallWhereTheServerPutsIt) {
  open(kSpectateScreenshot, "render-spectate");
  ::unsetenv("DISPLAY");  // render as on a machine without X: EGL surfaceless
  MatchRecorder recorder(kSpectateScreenshot);
  startServer({"--fast"});
  // Bots that think for a while leave the table at rest between shots.
  startBot("alice", 5, {"--think", "2.5"});
  startBot("bob", 6, {"--think", "2.5"});
  ASSERT_TRUE(recorder.pump(60s, [&] {
    const MatchView* v = recorder.latest(recorder.firstMatch());
    return (v && v->shot_number >= 2) || stalledOnLayout(recorder);
  })) << logs();
  const std::string match = recorder.firstMatch();

  // A shot may start while the client draws; then its frame matches no layout at rest: retry.
  nlohmann::json info;
  bool at_rest = false;
  for (int attempt = 0; attempt < 4 && !at_rest; ++attempt) {
    const std::string png = file("spectate-" + std::to_string(attempt) + ".png");
    const std::string json = file("spectate-" + std::to_string(attempt) + ".json");
    ChildProcess& client =
        start("pool-client",
              {"--domain", std::to_string(kSpectateScreenshot), "--spectate", "any", "--screenshot",
               png, "--screenshot-info", json, "--frames", "3", "--timeout", "60"},
              "client-" + std::to_string(attempt));
    std::optional<int> code;
    ASSERT_TRUE(recorder.pump(90s, [&] { return (code = client.waitExit(0ms)).has_value(); }));
    ASSERT_EQ(*code, 0) << client.err();
    std::ifstream in(json);
    info = nlohmann::json::parse(in, nullptr, false);
    ASSERT_FALSE(info.is_discarded()) << "sidecar " << json;
    at_rest = matchesALayout(info.at("balls"), recorder.states(match));
    if (at_rest) {
      const Image image = loadPng(png);
      ASSERT_EQ(image.width, info.at("width").get<int>());
      const render::Camera camera{vec3Of(info["camera"]["eye"]), vec3Of(info["camera"]["target"]),
                                  info["camera"]["fov_y_deg"].get<float>()};
      const auto r = info.at("ball_radius").get<float>();
      const glm::vec3 side = glm::normalize(glm::cross(camera.target - camera.eye, {0, 0, 1})) * r;
      ASSERT_EQ(info.at("balls").size(), 16u);
      int pocketed = 0;
      for (const auto& b : info.at("balls")) {
        const int id = b.at("id").get<int>();
        const glm::vec3 p = vec3Of(b.at("pos"));
        const glm::vec3 c = render::projectToPixels(camera, image.width, image.height, p);
        const glm::vec3 e = render::projectToPixels(camera, image.width, image.height, p + side);
        const double radius = glm::length(glm::vec2(e) - glm::vec2(c));
        pocketed += b.at("pocketed").get<bool>() ? 1 : 0;
        // The whole disc: a stripe seen end-on shows its band only near the rim. Balls may lie
        // between the lamps' pools of light, in the hall's dimmer light.
        EXPECT_GE(countInDisc(image, c.x, c.y, radius,
                              [&](const Rgb& px) { return ballColourInAnyLight(id, px); }),
                  3)
            << "ball " << id << (b.at("pocketed").get<bool>() ? " (in the trough)" : "") << " at "
            << c.x << ", " << c.y;
      }
      std::printf("checked 16 balls, %d of them in the trough\n", pocketed);
    }
  }
  EXPECT_TRUE(at_rest) << "no screenshot caught the table at rest in 4 tries";
}

}  // namespace
}  // namespace pool::client::test
