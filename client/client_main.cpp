// pool-client: the player's client: the window (lobby, play, watch), the headless spectator
// (--spectate MATCH --no-window --json) and offscreen screenshots (--screenshot FILE).
#include <CLI/CLI.hpp>
#include <atomic>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <iostream>

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

/// How the client runs: the headless spectator, or the window.
enum class Mode { Spectate, Window };

struct Flags {
  std::uint32_t domain = 0;
  std::string spectate;
  bool no_window = false;
  bool json = false;
  bool follow = false;   // keep watching after the match is over
  double timeout = 0.0;  // s; 0: none
  pool::render::ScreenshotOptions screenshot;
  pool::ui::WindowOptions window;
};

int runSpectator(const Flags& flags) {
  using namespace pool::client;
  GameClient client({flags.domain, "", "spectator", {}, {}});
  SpectatorConfig config;
  config.match = flags.spectate;
  config.exit_when_over = !flags.follow;
  Spectator spectator(client, config, [](const std::string& line) {
    std::cout << line << '\n' << std::flush;
  });
  const auto start = std::chrono::steady_clock::now();
  auto now = [&] {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  };
  while (!spectator.done() && !g_stop) {
    if (flags.timeout > 0 && now() > flags.timeout) return 3;
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

}  // namespace

int main(int argc, char** argv) {
  Flags flags;
  CLI::App app{"pool-client: play or watch 8-ball over DDS"};
  app.add_option("--domain", flags.domain, "DDS domain id")->check(CLI::Range(0, 232));
  app.add_option("--spectate", flags.spectate, "watch MATCH (an id, or 'any': the first in play)");
  app.add_flag("--no-window", flags.no_window, "no window (the only spectator mode for now)");
  app.add_flag("--json", flags.json, "print JSON lines: states, shot results, frame counts");
  app.add_flag("--follow", flags.follow, "keep watching after the match is over");
  app.add_option("--timeout", flags.timeout, "exit (code 3) after this many seconds; 0: never");
  app.add_option("--name", flags.window.name, "the player's name (window)");
  auto* hotseat =
      app.add_flag("--hotseat", flags.window.hotseat, "two players on this screen (window)");
  std::string forget_server;
  app.add_option("--forget-server-key", forget_server,
                 "forget the key pinned for SERVER-ID (in $XDG_CONFIG_HOME/pool/servers) and exit: "
                 "for a server whose database was replaced on purpose");
  bool fresh_identity = false;
  app.add_flag("--fresh-identity", fresh_identity,
               "play with a new key, keeping nothing (default: each player's key and seat are kept "
               "in $XDG_CONFIG_HOME/pool/players, so a restarted window takes its seat back)");
  app.add_flag("--mute", flags.window.mute, "no sound (window)");
  app.add_flag("--play", flags.window.play, "take a seat at once, skipping the lobby (window)");
  app.add_flag("--practice", flags.window.practice,
               "open a practice table of your own at once, skipping the lobby (window)");
  app.add_option("--bot", flags.window.bot,
                 "play a bot of this level at a fresh table at once, skipping the lobby: beginner, "
                 "club, league or pro (the window starts pool-bot and stops it when it closes)")
      ->check(CLI::IsMember({"beginner", "club", "league", "pro"}))
      ->excludes(hotseat);
  app.add_option("--practice-file", flags.window.practice_file,
                 "where a practice table saves (F5) and loads (F6) its scenario file")
      ->capture_default_str();
  app.add_option("--match", flags.window.match, "with --play: the match to join");
  app.add_option("--script", flags.window.script, "play timed key presses from FILE (window)");
  app.add_option("--capture", flags.window.capture, "write the window's last frame to this PNG");
  app.add_flag("--log-frames", flags.window.log_frames,
               "with --json in a window: a line for every frame drawn (camera, cue ball, mouse)");
  app.add_option("--table", flags.window.table, "table spec the window draws");
  app.add_option("--width", flags.window.width, "window width")->check(CLI::Range(320, 8192));
  app.add_option("--height", flags.window.height, "window height")->check(CLI::Range(240, 8192));
  app.add_option("--screenshot", flags.screenshot.path,
                 "render offscreen and write the last frame to this PNG");
  app.add_option("--screenshot-info", flags.screenshot.info_path,
                 "--screenshot: also write the camera and the balls drawn to this JSON file");
  app.add_option("--frames", flags.screenshot.frames, "frames to render with --screenshot")
      ->check(CLI::PositiveNumber);
  app.add_option("--scene", flags.screenshot.scene,
                 "scene for --screenshot: rack (overview), aim (the aiming view of the rack), top "
                 "(a few balls from above), eightball")
      ->check(CLI::IsMember({"rack", "aim", "top", "eightball"}));
  auto& aim = flags.screenshot.aim;
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
  app.add_option("--cue-at", aim.cue_at, "--scene aim: the cue ball's x y on the table, m")
      ->expected(2);
  app.add_option("--balls", aim.balls,
                 "--scene aim: ID X Y of each object ball (m), instead of the rack")
      ->expected(3, 45);
  app.add_flag("--hud", aim.hud,
               "--scene aim: drawn with the window's HUD as a player sees it, the view framed");
  app.add_option("--camera-elevation", aim.camera_elevation_deg,
                 "--scene aim: the aiming view raised to this angle, degrees");
  app.add_option("--question", flags.screenshot.question,
                 "--scene eightball: the question the Magic Eight Ball answers");
  app.add_option("--seed", flags.screenshot.seed, "--scene eightball: the Magic Eight Ball's seed");
  std::string quality;
  app.add_option("--quality", quality,
                 "drawing preset: full, light (the 3-D scene at lower resolution) or auto (light "
                 "under software OpenGL); default: the window's settings (auto), full for "
                 "--screenshot")
      ->check(CLI::IsMember({"auto", "full", "light"}));
  app.add_flag("--wireframe", flags.screenshot.render.wireframe, "--screenshot: polygons as lines");
  bool no_textures = false, no_lighting = false;
  app.add_flag("--no-textures", no_textures, "--screenshot: flat colours, no numbers or grain");
  app.add_flag("--no-lighting", no_lighting, "--screenshot: unlit colours");
  CLI11_PARSE(app, argc, argv);
  flags.window.keep_identity = !fresh_identity;
  flags.screenshot.render.textures = !no_textures;
  if (!quality.empty()) flags.window.quality = quality;
  if (quality == "light") {
    flags.screenshot.render = withQuality(flags.screenshot.render, pool::render::Quality::Light);
  }
  flags.screenshot.render.lighting = !no_lighting;

  if (!forget_server.empty()) return forgetServerKey(forget_server);

  std::signal(SIGINT, onSignal);
  std::signal(SIGTERM, onSignal);
  if (!flags.screenshot.path.empty() && !flags.spectate.empty()) {
    pool::client::SpectateScreenshotConfig config{
        flags.domain, flags.spectate, flags.timeout, [] { return g_stop.load(); }, {}};
    if (flags.json) config.emit = [](const std::string& line) { std::cout << line << '\n'; };
    return pool::client::runSpectateScreenshot(config, flags.screenshot);
  }
  if (!flags.screenshot.path.empty() && flags.screenshot.scene == "aim") {
    return pool::ui::runAimScreenshot(flags.screenshot);
  }
  if (!flags.screenshot.path.empty()) return pool::render::runScreenshot(flags.screenshot);

  const Mode mode = flags.spectate.empty() || !flags.no_window ? Mode::Window : Mode::Spectate;
  if (mode == Mode::Window) {
    if (flags.no_window) {
      std::cerr << "--no-window needs --spectate MATCH\n";
      return 2;
    }
    flags.window.domain = flags.domain;
    flags.window.spectate = flags.spectate;
    flags.window.json = flags.json;
    flags.window.timeout = flags.timeout;
    return pool::ui::runWindow(flags.window, g_stop);
  }
  if (!flags.json) {
    std::cerr << "--spectate MATCH --no-window needs --json\n";
    return 2;
  }
  try {
    return runSpectator(flags);
  } catch (const pool::net::DdsError& e) {
    std::cerr << "DDS: " << e.what() << '\n';
    return 1;
  }
}
