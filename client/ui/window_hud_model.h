// The HUD's model at the window: what its panes show this frame, from the window's parts.
#pragma once

#include <string>

#include "client/ui/hud.h"
#include "client/ui/window_parts.h"

namespace pool::ui {

/// What the HUD shows this frame; `placement_problem`: why the cue ball in hand cannot go where
/// it is (empty: it can).
HudInput hudInputOf(const WindowParts& w, const std::string& placement_problem);

}  // namespace pool::ui
