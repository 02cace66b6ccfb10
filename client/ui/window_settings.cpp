// The window's settings file: loaded once, saved when changed, and where it is kept.
#include "client/ui/window_settings.h"

namespace pool::ui {

WindowSettings::WindowSettings(bool keep) {
  if (!keep) return;
  path_ = app::defaultSettingsPath();
  if (path_.empty()) return;
  auto loaded = app::loadSettings(path_);
  if (loaded) {
    settings_ = *loaded;
  } else {
    problem_ = "settings not used (the file is left as it is): " + loaded.error();
  }
}

app::Settings WindowSettings::current(const app::Toggles& toggles, bool full_screen) const {
  app::Settings s = settings_;
  s.aim_line = toggles.aim_line;
  s.vectors = toggles.vectors;
  s.full_screen = full_screen;
  return s;
}

std::string WindowSettings::whereKept() const {
  if (!problem_.empty()) return problem_;
  if (path_.empty()) return "settings are not kept (no config folder)";
  return "kept in " + path_.string();
}

bool WindowSettings::choose(const app::Settings& chosen) {
  settings_.stroke_mm = chosen.stroke_mm;
  settings_.pane_places = chosen.pane_places;
  settings_.follow_cue = chosen.follow_cue;
  settings_.volume = chosen.volume;
  if (chosen.quality == settings_.quality) return false;
  settings_.quality = chosen.quality;
  return true;
}

std::optional<app::SessionNote> WindowSettings::keep(const app::Settings& now) {
  const bool unchanged = now == settings_;
  settings_ = now;
  if (unchanged || path_.empty() || !problem_.empty()) return std::nullopt;
  if (auto saved = app::saveSettings(path_, now); !saved) {
    problem_ = "settings not kept: " + saved.error();
    return app::SessionNote{problem_, true};
  }
  return std::nullopt;
}

}  // namespace pool::ui
