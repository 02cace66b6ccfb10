// Script steps (keys, the mouse, quit) applied to the controls.
#include "client/ui/window_script.h"

namespace pool::ui {

bool playScriptFrame(app::ScriptPlayer& script, app::Controls& controls,
                     const app::MatchSession& session, ScriptMouse& mouse, double at) {
  app::ScriptConditions now;
  now.can_aim = controls.mode() == app::ControlMode::Aiming;
  now.replaying = session.replay().playing();
  const app::StoredReplay& stored = session.stored();
  const bool stored_moving = session.stage() == app::SessionStage::Lobby && stored.isOpen() &&
                             stored.problem().empty() && (stored.waiting() || !stored.atRest(at));
  now.moving = session.inMotion() || stored_moving;
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
        mouse.at = {step.x, step.y};
        controls.mouseButton(app::MouseButton::Left, true, step.x, step.y, step.mods);
        mouse.down = true;
        break;
      case app::ScriptStep::Kind::MouseOnCue:
        if (mouse.cue_ball) mouse.at = *mouse.cue_ball;
        controls.mouseMove(mouse.at.x(), mouse.at.y());
        controls.mouseButton(app::MouseButton::Left, true, mouse.at.x(), mouse.at.y());
        break;
      case app::ScriptStep::Kind::MouseMove:
        mouse.at = {step.x, step.y};
        controls.mouseMove(step.x, step.y);
        break;
      case app::ScriptStep::Kind::MouseBy:
        mouse.at += Eigen::Vector2d(step.x, step.y);
        controls.mouseMove(mouse.at.x(), mouse.at.y());
        break;
      case app::ScriptStep::Kind::MouseRelease:
        if (step.count == 0) mouse.at = {step.x, step.y};
        controls.mouseButton(app::MouseButton::Left, false, mouse.at.x(), mouse.at.y());
        mouse.down = false;
        break;
      case app::ScriptStep::Kind::Capture:
        mouse.capture = step.path;
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
