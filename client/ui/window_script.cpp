// Script steps (keys, the mouse, quit) applied to the controls.
#include "client/ui/window_script.h"

namespace pool::ui {

bool playScriptFrame(app::ScriptPlayer& script, app::Controls& controls,
                     const app::MatchSession& session) {
  app::ScriptConditions now;
  now.can_aim = controls.mode() == app::ControlMode::Aiming;
  if (const auto* v = session.view()) {
    now.shot_number = v->shot_number;
    now.over = v->phase == client::MatchPhase::Over;
    now.at_table =
        !now.over && session.stage() == app::SessionStage::Playing && !session.localSeats().empty();
  }
  bool quit = false;
  for (const auto& step : script.frame(now)) {
    switch (step.kind) {
      case app::ScriptStep::Kind::Down:
        controls.keyDown(step.key, step.mods);
        break;
      case app::ScriptStep::Kind::Up:
        controls.keyUp(step.key);
        break;
      case app::ScriptStep::Kind::MousePress:
        controls.mouseButton(app::MouseButton::Left, true, step.x, step.y);
        break;
      case app::ScriptStep::Kind::MouseMove:
        controls.mouseMove(step.x, step.y);
        break;
      case app::ScriptStep::Kind::MouseRelease:
        controls.mouseButton(app::MouseButton::Left, false, step.x, step.y);
        break;
      case app::ScriptStep::Kind::Quit:
        quit = true;
        break;
      default:
        break;
    }
  }
  return quit;
}

}  // namespace pool::ui
