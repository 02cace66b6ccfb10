// The HUD's model read from the session, the controls, the turn, the notes and the settings.
#include "client/ui/window_hud_model.h"

namespace pool::ui {

HudInput hudInputOf(const WindowParts& w, const std::string& placement_problem) {
  const app::MatchSession& session = w.session;
  HudInput in;
  in.view = session.view();
  in.match = session.match();
  in.spectating = session.stage() == app::SessionStage::Spectating;
  in.local_seats = session.localSeats();
  in.local_shooter = w.controls.mode() == app::ControlMode::Aiming ? w.turn.aimingSeat() : -1;
  in.live_aim = session.followedAim();
  in.in_motion = session.inMotion();
  in.controls = &w.controls;
  in.placement_problem = placement_problem;
  in.last_verdict = session.lastVerdict();
  in.notes = &w.notes.shown();
  in.banner = session.banner();
  in.log = &session.shotLog();
  in.help = w.controls.toggles().help;
  in.panes = w.controls.toggles().panes;
  in.names = session.names();
  in.settings = w.settings.current(w.controls.toggles(), w.window.fullScreen());
  in.can_concede = w.desk.canConcede();
  in.can_replay = session.replay().shot().has_value() && !session.inMotion();
  in.last_shot = session.lastShot();
  in.replaying = session.replay().playing();
  in.concede_asked = w.desk.concedeAsked();
  in.settings_note = w.settings.whereKept();
  return in;
}

}  // namespace pool::ui
