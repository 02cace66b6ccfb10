// The keys and the HUD's buttons at the window: match requests, practice keys, settings.
#include "client/ui/window_commands.h"

namespace pool::ui {
namespace {

/// A practice table's key: its command goes out; a remembered shot is sent for the seat aiming.
void practiceKey(const WindowParts& w, app::Key key) {
  PracticeOutcome outcome = w.practice.key(key, w.session, w.controls);
  if (outcome.note) w.notes.add(std::move(*outcome.note));
  if (outcome.shot && w.turn.aimingSeat() >= 0) {
    w.controls.stopAiming();
    w.turn.send(std::move(*outcome.shot));
  }
}

/// A number key answers the rules' choice for the seat aiming here: the option it numbers in the
/// Your choice pane (a choice that shoots goes with the next shot, one that does not at once).
void chooseByKey(const WindowParts& w, int index) {
  const client::MatchView* v = w.session.view();
  if (!v || w.turn.aimingSeat() < 0 || index >= static_cast<int>(v->options.size())) return;
  w.turn.chooseOption(protocol::optionOf(v->options[static_cast<std::size_t>(index)]));
}

/// The settings pane's choices: the aim aids, the stroke, the window, the quality.
void chooseSettings(const WindowParts& w, const app::Settings& chosen) {
  w.controls.setAimAids(chosen.aim_line, chosen.vectors);
  w.controls.setStrokeScale(chosen.stroke_mm / 1000.0);
  w.window.setFullScreen(chosen.full_screen);
  if (w.settings.choose(chosen)) applyQuality(w, w.settings.settings().quality);
}

/// Writes the settings when they changed.
void keepSettings(const WindowParts& w) {
  const app::Settings now = w.settings.current(w.controls.toggles(), w.window.fullScreen());
  if (auto problem = w.settings.keep(now)) w.notes.add(std::move(*problem));
}

}  // namespace

void handleKeys(const WindowParts& w, double now) {
  const client::MatchView* v = w.session.view();
  const bool over =
      v && v->phase == client::MatchPhase::Over && w.session.stage() == app::SessionStage::Playing;
  w.desk.dropStaleQuestion();
  for (const app::Key key : w.controls.takeRequests()) {
    if (key == app::Key::F11) w.window.setFullScreen(!w.window.fullScreen());
    if (key == app::Key::Q) w.desk.askConcede();
    if (key == app::Key::I) w.desk.startReplay(1.0, now);
    if (w.desk.concedeAsked() && (key == app::Key::Y || key == app::Key::Escape)) {
      w.desk.answerConcede(key == app::Key::Y);
      continue;  // the answer to the question, nothing else
    }
    if (const auto index = app::choiceIndexOf(key)) chooseByKey(w, *index);
    if (w.session.stage() == app::SessionStage::Playing) practiceKey(w, key);
    if (!over) continue;
    if (key == app::Key::N) {
      w.desk.newGame();
      return;
    }
    if (key == app::Key::R) w.desk.rematch();
  }
}

void handleHud(const WindowParts& w, const HudActions& actions, double now) {
  if (actions.option) w.turn.chooseOption(*actions.option);
  if (actions.rematch) w.desk.rematch();
  if (actions.concede) w.desk.askConcede();
  if (actions.replay) w.desk.startReplay(*actions.replay, now);
  if (actions.concede_answer) w.desk.answerConcede(*actions.concede_answer);
  if (actions.visit_room) w.desk.setInRoom(true);
  if (actions.new_game) w.desk.newGame();
  if (actions.settings) chooseSettings(w, *actions.settings);
  keepSettings(w);
  if (actions.leave) {
    w.controls.stopAiming();
    w.session.leave();
  }
}

void applyQuality(const WindowParts& w, const std::string& chosen) {
  w.notes.add({w.scene.applyQuality(chosen), false});
}

}  // namespace pool::ui
