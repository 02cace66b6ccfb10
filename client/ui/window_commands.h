// The player's requests at the window, from the keys and from the HUD, carried out on its parts.
#pragma once

#include "client/ui/hud.h"
#include "client/ui/window_parts.h"

namespace pool::ui {

/// The keys the controls leave to the window (R, N, F11, I; Q, then Y or Esc; a practice
/// table's keys), pressed since the last frame at `now` (s).
void handleKeys(const WindowParts& w, double now);

/// What the player clicked in the HUD this frame at `now` (s); the settings are written when
/// they changed.
void handleHud(const WindowParts& w, const HudActions& actions, double now);

/// Draws with the preset `chosen` (auto, full or light) from the next frame on, and says which.
void applyQuality(const WindowParts& w, const std::string& chosen);

}  // namespace pool::ui
