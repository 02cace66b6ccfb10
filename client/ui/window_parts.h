// The parts of a window that the player's keys, the HUD and the lobby act on, by reference.
#pragma once

#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/ui/window_glfw.h"
#include "client/ui/window_match_desk.h"
#include "client/ui/window_notes.h"
#include "client/ui/window_practice.h"
#include "client/ui/window_scene.h"
#include "client/ui/window_settings.h"
#include "client/ui/window_turn.h"
#include "game/loaded_table.h"

namespace pool::ui {

/// One window's parts, all owned by the window.
struct WindowParts {
  const game::LoadedTable& table;
  app::MatchSession& session;
  app::Controls& controls;
  GlfwWindow& window;
  WindowSettings& settings;
  WindowScene& scene;
  WindowNotes& notes;
  TurnDesk& turn;
  MatchDesk& desk;
  PracticeDesk& practice;
};

}  // namespace pool::ui
