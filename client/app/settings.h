// The player's settings kept between runs: full screen, volume, the aim aids and the drawing
// quality, in a small text file in the user's config folder ($XDG_CONFIG_HOME/pool/settings.conf).
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>

#include "core/result.h"

namespace pool::app {

struct Settings {
  bool full_screen = false;
  double volume = 1.0;   ///< 0–1, the sound's master gain
  bool aim_line = true;  ///< aim line and ghost ball (G)
  bool vectors = false;  ///< direction arrows (V)
  /// The drawing preset: "auto" (light under a software renderer, else full), "full" or "light".
  std::string quality = "auto";
  /// A mouse stroke's scale: mm of cue a pixel of mouse (0.2–5; ControlRates::stroke_scale).
  double stroke_mm = 1.0;
  bool follow_cue = false;  ///< the watching view follows the cue ball while the balls run
  /// Where the player left a pane ("match", "shot", "log"): its top-left corner as fractions of
  /// the window's width and height; a pane not named here stays at its anchor.
  std::map<std::string, std::array<double, 2>> pane_places;

  bool operator==(const Settings&) const = default;
};

/// `$XDG_CONFIG_HOME/pool/settings.conf` (or `~/.config/pool/settings.conf`); empty when neither
/// is set.
std::filesystem::path defaultSettingsPath();

/// True for the quality names a settings file may hold: auto, full, light.
bool knownQuality(const std::string& name);

/// True for the panes whose place a settings file may hold (`pane_<name> = x, y`): match, shot,
/// log.
bool knownPane(const std::string& name);

/// Reads `key = value` lines ('#' starts a comment). A missing file gives the defaults. An unknown
/// key, a bad value, a volume outside [0, 1], a stroke scale outside [0.2, 5] or a quality not
/// named above fails with the line's number, and nothing of the file is used.
Result<Settings> loadSettings(const std::filesystem::path& path);

/// Writes `settings` to `path` (its folder made if needed) through a temporary file renamed over
/// it, so a crash never leaves half a file.
Result<bool> saveSettings(const std::filesystem::path& path, const Settings& settings);

}  // namespace pool::app
