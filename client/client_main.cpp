// pool-client: the player's client: the window (lobby, play, watch), the headless spectator
// (--spectate MATCH --no-window --json) and offscreen screenshots (--screenshot FILE).
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>

#include "client/bot/ai/bot_level.h"
#include "client/net/game_client.h"
#include "client/net/server_pins.h"
#include "client/render/screenshot.h"
#include "client/spectate/spectate_screenshot.h"
#include "client/spectate/spectator.h"
#include "client/ui/aim_screenshot.h"
#include "client/ui/window_app.h"
#include "core/text.h"
#include "net/dds_error.h"
#include "physics/shot_limits.h"
#include "protocol/server_signature.h"

namespace {

std::atomic<bool> g_stop{false};

void onSignal(int) {
  g_stop = true;
}

/// What pool-client's flags ask for: the flags' values as given (addClientFlags), with the
/// window's and the screenshot's options completed from them (completeOptions).
struct ClientConfig {
  std::uint32_t domain = 0;
  std::string spectate;
  bool no_window = false;
  bool json = false;
  bool follow = false;   // keep watching after the match is over
  double timeout = 0.0;  // s; 0: none
  std::string forget_server;
  bool fresh_identity = false;
  bool no_textures = false;
  bool no_lighting = false;
  pool::render::ScreenshotOptions screenshot;
  pool::ui::WindowOptions window;
};

/// Every flag of pool-client, each bound to its field of `c`.
void addClientFlags(CLI::App& app, ClientConfig& c) {
  app.add_option("--domain", c.domain, "DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--spectate", c.spectate, "watch MATCH (an id, or 'any': the first in play)");
  app.add_flag("--no-window", c.no_window, "no window (the only spectator mode for now)");
  app.add_flag("--json", c.json, "print JSON lines: states, shot results, frame counts");
  app.add_flag("--follow", c.follow, "keep watching after the match is over");
  app.add_option("--timeout", c.timeout, "exit (code 3) after this many seconds; 0: never");
  app.add_option("--name", c.window.name, "the player's name (window)");
  auto* hotseat =
      app.add_flag("--hotseat", c.window.hotseat, "two players on this screen (window)");
  app.add_option("--forget-server-key", c.forget_server,
                 "forget the key pinned for SERVER-ID (in $XDG_CONFIG_HOME/pool/servers) and exit: "
                 "for a server whose database was replaced on purpose");
  app.add_flag("--fresh-identity", c.fresh_identity,
               "play with a new key, keeping nothing (default: each player's key and seat are kept "
               "in $XDG_CONFIG_HOME/pool/players, so a restarted window takes its seat back)");
  app.add_flag("--mute", c.window.mute, "no sound (window)");
  app.add_flag("--play", c.window.play, "take a seat at once, skipping the lobby (window)");
  app.add_flag("--practice", c.window.practice,
               "open a practice table of your own at once, skipping the lobby (window)");
  app.add_option("--bot", c.window.bot,
                 "play a bot of this level at a fresh table at once, skipping the lobby: beginner, "
                 "club, league or pro (the window starts pool-bot and stops it when it closes)")
      ->check(CLI::IsMember(pool::bot::levelNames()))
      ->excludes(hotseat);
  app.add_option("--practice-file", c.window.practice_file,
                 "where a practice table saves (F5) and loads (F6) its scenario file")
      ->capture_default_str();
  app.add_option("--match", c.window.match, "with --play: the match to join");
  auto* replay = app.add_option("--replay", c.window.replay,
                                "replay a stored shot of MATCH at once, in the lobby's stead "
                                "(window; Previous and Next walk its shots)")
                     ->excludes("--spectate")
                     ->excludes("--play")
                     ->excludes("--practice")
                     ->excludes("--bot");
  app.add_option("--shot", c.window.replay_shot,
                 "with --replay: the shot to open (from 1; default: the match's last)")
      ->check(CLI::Range(1u, 1000000000u))
      ->needs(replay);
  app.add_option("--script", c.window.script, "play timed key presses from FILE (window)");
  app.add_option("--capture", c.window.capture, "write the window's last frame to this PNG");
  app.add_flag("--log-frames", c.window.log_frames,
               "with --json in a window: a line for every frame drawn (camera, cue ball, mouse)");
  app.add_option("--table", c.window.table,
                 "table spec the window draws (and the rack, aim and top screenshot scenes)");
  app.add_option("--width", c.window.width, "window width")->check(CLI::Range(320, 8192));
  app.add_option("--height", c.window.height, "window height")->check(CLI::Range(240, 8192));
  app.add_option("--screenshot", c.screenshot.path,
                 "render offscreen and write the last frame to this PNG");
  app.add_option("--screenshot-info", c.screenshot.info_path,
                 "--screenshot: also write the camera and the balls drawn to this JSON file");
  app.add_option("--frames", c.screenshot.frames, "frames to render with --screenshot")
      ->check(CLI::PositiveNumber);
  app.add_option("--scene", c.screenshot.scene,
                 "scene for --screenshot: rack (overview), aim (the aiming view of the rack), top "
                 "(a few balls from above), eightball")
      ->check(CLI::IsMember({"rack", "aim", "top", "eightball"}));
  auto& aim = c.screenshot.aim;
  app.add_option("--aim", aim.yaw_deg, "--scene aim: cue heading, degrees (0 = toward the foot)");
  app.add_option("--tip-side", aim.tip_side, "--scene aim: tip right of centre, fraction of R");
  app.add_option("--tip-height", aim.tip_height, "--scene aim: tip above centre, fraction of R");
  app.add_option("--elevation", aim.elevation_deg, "--scene aim: cue elevation, degrees")
      ->check(CLI::Range(0.0, pool::physics::kMaxElevationDeg));
  app.add_option("--power", aim.power, "--scene aim: power bar, 0-1 (draws the cue back)")
      ->check(CLI::Range(0.0, 1.0));
  app.add_option("--camera-distance", aim.camera_distance,
                 "--scene aim: the aiming view this far from the cue ball, m")
      ->check(CLI::PositiveNumber);
  app.add_option("--cue-at", aim.cue_at,
                 "--scene aim, rack or top: the cue ball's x y on the table, m")
      ->expected(2);
  app.add_option("--balls", aim.balls,
                 "--scene aim, rack or top: ID X Y of each object ball (m), instead of the "
                 "scene's")
      ->expected(3, 45);
  app.add_flag("--hud", aim.hud,
               "--scene aim: drawn with the window's HUD as a player sees it, the view framed");
  app.add_option("--camera-elevation", aim.camera_elevation_deg,
                 "--scene aim: the aiming view raised to this angle, degrees");
  app.add_option("--question", c.screenshot.question,
                 "--scene eightball: the question the Magic Eight Ball answers");
  app.add_option("--seed", c.screenshot.seed, "--scene eightball: the Magic Eight Ball's seed");
  app.add_option("--quality", c.window.quality,
                 "drawing preset: high (anti-aliased, shadow maps, reflections), full, light (the "
                 "3-D scene at lower resolution) or auto (light under software OpenGL, high "
                 "otherwise); default: the window's settings (auto), full for --screenshot")
      ->check(CLI::IsMember({"auto", "high", "full", "light"}));
  app.add_flag("--wireframe", c.screenshot.render.wireframe, "--screenshot: polygons as lines");
  app.add_flag("--no-textures", c.no_textures, "--screenshot: flat colours, no numbers or grain");
  app.add_flag("--no-lighting", c.no_lighting, "--screenshot: unlit colours");
}

/// The options the flags imply beyond their own fields: the kept identity, the screenshot's
/// drawing (its quality from --quality, which the window reads as given), and what the window
/// shares with the spectator.
void completeOptions(ClientConfig& c) {
  c.window.keep_identity = !c.fresh_identity;
  c.screenshot.render.textures = !c.no_textures;
  c.screenshot.table = c.window.table;
  if (c.window.quality == "light" || c.window.quality == "high") {
    const auto setting = *pool::render::parseQualitySetting(c.window.quality);
    c.screenshot.render =
        withQuality(c.screenshot.render, pool::render::resolveQuality(setting, ""));
  }
  c.screenshot.render.lighting = !c.no_lighting;
  c.window.domain = c.domain;
  c.window.spectate = c.spectate;
  c.window.json = c.json;
  c.window.timeout = c.timeout;
}

int runSpectator(const ClientConfig& c) {
  using namespace pool::client;
  GameClient client({c.domain, "", "spectator", {}, {}});
  SpectatorConfig config;
  config.match = c.spectate;
  config.exit_when_over = !c.follow;
  Spectator spectator(client, config, [](const std::string& line) {
    std::cout << line << '\n' << std::flush;
  });
  const auto start = std::chrono::steady_clock::now();
  auto now = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  while (!spectator.done() && !g_stop) {
    if (c.timeout > 0 && now() > c.timeout) return 3;
    client.wait(std::chrono::milliseconds(20));
    spectator.step(now());
  }
  return 0;
}

/// --forget-server-key: drops the pin of `server` from the user's pin file.
int forgetServerKey(const std::string& server) {
  using namespace pool;
  const auto file = client::defaultServerPinFile();
  client::ServerPins pins(file);
  const auto* pinned = pins.pinned(server);
  if (!pinned) {
    std::cerr << "no key is pinned for server '" << escapedForLog(server) << "' in "
              << file.string() << '\n';
    return 1;
  }
  const std::string was = protocol::fingerprint(*pinned);
  pins.forget(server);
  if (!pins.fileProblem().empty()) {
    std::cerr << pins.fileProblem() << '\n';
    return 1;
  }
  std::cout << "forgot key " << was << " of server '" << escapedForLog(server)
            << "': the next key it shows is pinned\n";
  return 0;
}

/// --screenshot: a spectated match's frames, the aiming view, or another scene offscreen.
int runScreenshot(const ClientConfig& c) {
  if (!c.spectate.empty()) {
    pool::client::SpectateScreenshotConfig config{
        c.domain, c.spectate, c.timeout, [] { return g_stop.load(); }, {}};
    if (c.json) config.emit = [](const std::string& line) { std::cout << line << '\n'; };
    return pool::client::runSpectateScreenshot(config, c.screenshot);
  }
  if (c.screenshot.scene == "aim") return pool::ui::runAimScreenshot(c.screenshot);
  return pool::render::runScreenshot(c.screenshot);
}

/// The headless spectator (--spectate MATCH --no-window --json).
int runHeadless(const ClientConfig& c) {
  if (!c.json) {
    std::cerr << "--spectate MATCH --no-window needs --json\n";
    return 2;
  }
  try {
    return runSpectator(c);
  } catch (const pool::net::DdsError& e) {
    std::cerr << "DDS: " << e.what() << '\n';
    return 1;
  }
}

/// Runs what the flags ask for: a pin forgotten, a screenshot, the window or the spectator.
int run(const ClientConfig& c) {
  if (!c.forget_server.empty()) return forgetServerKey(c.forget_server);
  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  if (!c.screenshot.path.empty()) return runScreenshot(c);
  if (!c.spectate.empty() && c.no_window) return runHeadless(c);
  if (c.no_window) {
    std::cerr << "--no-window needs --spectate MATCH\n";
    return 2;
  }
  return pool::ui::runWindow(c.window, g_stop);
}

}  // namespace

int main(int argc, char** argv) {
  ClientConfig config;
  CLI::App app{"pool-client: play or watch 8-ball over DDS"};
  addClientFlags(app, config);
  CLI11_PARSE(app, argc, argv);
  completeOptions(config);
  return run(config);
}
