// The window's input script: each frame's scripted key presses into the controls.
#pragma once

#include "client/app/controls.h"
#include "client/app/input_script.h"
#include "client/app/match_session.h"

namespace pool::ui {

/// Plays this frame's steps of `script` on `controls`, given whether they can aim and the
/// session's shot number. True when the script says to quit.
bool playScriptFrame(app::ScriptPlayer& script, app::Controls& controls,
                     const app::MatchSession& session);

}  // namespace pool::ui
