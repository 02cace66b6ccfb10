// The windowed client: a GLFW window with the table, the controls, the HUD and the lobby, playing
// or watching a match on the network.
#pragma once

#include <atomic>
#include <cstdint>
#include <string>

namespace pool::ui {

/// How the window starts.
struct WindowOptions {
  std::uint32_t domain = 0;
  std::string name = "Player";
  bool hotseat = false;  ///< two seats on this screen
  /// Keep each player's key and seat in the config folder, so a restarted window takes its seat
  /// back (false: a fresh key each run).
  bool keep_identity = true;
  bool mute = false;     ///< no sound (without an audio device it is silent anyway)
  bool play = false;     ///< take a seat at once (in `match`, or the first free table)
  std::string spectate;  ///< watch this match at once ("any": the first in play)
  std::string match;     ///< with `play`: this match
  /// Replay a stored shot of this match at once, from the lobby (`pool-client --replay MATCH`):
  /// shot `replay_shot`, or its last when 0 (`--shot N`).
  std::string replay;
  std::uint32_t replay_shot = 0;
  std::string script;  ///< input script file (see client/app/input_script.h)
  bool json = false;   ///< print shots sent and messages as JSON lines on stdout
  /// With `json`: a line for every frame drawn (the camera, the cue ball as drawn and in pixels,
  /// the mouse, the playback): tests check the picture against the server's frames.
  bool log_frames = false;
  double timeout = 0.0;  ///< s; exit with code 3 after this long; 0: never
  std::string capture;   ///< write the last frame drawn to this PNG when the window closes
  std::string table = "wpa-9ft";
  int width = 1280;
  int height = 720;
  /// Drawing preset: auto, full or light (render_options.h); empty: the one in the settings file
  /// (auto without one). The settings pane changes it at once.
  std::string quality;
  /// Open a practice table of this window's own at once (`pool-client --practice`).
  bool practice = false;
  /// Play a bot of this level ("beginner", "club", "league", "pro") at the first free table at
  /// once (`pool-client --bot LEVEL`): the window starts pool-bot and stops it when it closes.
  std::string bot;
  /// Where a practice table's F5 saves and F6 loads a scenario file.
  std::string practice_file = "practice.json";
};

/// Runs the window until it is closed, the script quits or `stop` is set. Returns the exit code:
/// 0 closed, 1 no window or DDS, 2 bad options, 3 timed out.
int runWindow(const WindowOptions& options, const std::atomic<bool>& stop);

}  // namespace pool::ui
