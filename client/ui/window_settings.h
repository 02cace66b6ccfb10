// The window's settings file: read when the window opens, written whenever a setting changes.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/app/settings.h"

namespace pool::ui {

/// The settings file's path and what it holds (the defaults, and why, when it cannot be used).
class WindowSettings {
 public:
  /// Reads the settings file when `keep` (false: --fresh-identity keeps nothing between runs).
  explicit WindowSettings(bool keep);

  const app::Settings& settings() const { return settings_; }
  /// Why the file is not used or not written; empty when it is.
  const std::string& problem() const { return problem_; }
  /// The settings as they are now: these, with the aim aids' `toggles` and the window's
  /// `full_screen`.
  app::Settings current(const app::Toggles& toggles, bool full_screen) const;
  /// Where the settings are kept, or why they are not (shown with them).
  std::string whereKept() const;
  /// Takes the HUD's settings pane's choices the window does not hold itself: the stroke, the
  /// panes' places, the follow camera, the volume and the quality. True when the quality changed.
  bool choose(const app::Settings& chosen);
  /// Keeps `now` as the settings, writing the file when they changed (never over a file that
  /// could not be read); a note when writing failed.
  std::optional<app::SessionNote> keep(const app::Settings& now);

 private:
  std::filesystem::path path_;
  app::Settings settings_;
  std::string problem_;
};

}  // namespace pool::ui
