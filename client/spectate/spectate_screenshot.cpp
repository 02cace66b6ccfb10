// The spectating screenshot: a Spectator feeds the renderer's balls frame by frame.
#include "client/spectate/spectate_screenshot.h"

#include <chrono>
#include <iostream>

#include "client/spectate/spectator.h"
#include "net/dds_error.h"

namespace pool::client {

namespace {

std::vector<render::SceneBall> sceneBalls(const std::vector<physics::Ball>& balls) {
  std::vector<render::SceneBall> out;
  out.reserve(balls.size());
  for (const physics::Ball& b : balls) {
    out.push_back({b.id, b.pos, b.orient, !physics::onTable(b.state)});
  }
  return out;
}

int follow(const SpectateScreenshotConfig& config, const render::ScreenshotOptions& options) {
  GameClient client({config.domain, "", "spectator", {}, {}});
  SpectatorConfig watch;
  watch.match = config.match;
  watch.exit_when_over = false;
  Spectator spectator(client, watch, [&](const std::string& line) {
    if (config.emit) config.emit(line);
  });
  const auto start = std::chrono::steady_clock::now();
  const auto now = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  // Wait for the match's table (lobby entry) and a first layout or frame.
  const LobbyEntry* entry = nullptr;
  while (!entry || !spectator.latestBalls()) {
    if ((config.timeout > 0 && now() > config.timeout) || (config.stop && config.stop())) {
      std::cerr << "no table to draw from match '" << config.match << "' in time\n";
      return 3;
    }
    client.wait(std::chrono::milliseconds(20));
    spectator.step(now());
    if (!spectator.match().empty()) entry = client.lobby().find(spectator.match());
  }
  auto scene = render::tableScene(entry->table);
  if (!scene) {
    std::cerr << "table '" << entry->table << "': " << scene.error() << '\n';
    return 1;
  }
  return render::renderScreenshot(options, *scene, [&](render::Renderer& renderer, int) {
    spectator.step(now());
    renderer.setBalls(sceneBalls(*spectator.latestBalls()));
  });
}

}  // namespace

int runSpectateScreenshot(const SpectateScreenshotConfig& config,
                          const render::ScreenshotOptions& options) {
  try {
    return follow(config, options);
  } catch (const net::DdsError& e) {
    std::cerr << "DDS: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace pool::client
