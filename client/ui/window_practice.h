// A practice table at the window: its keys (undo, again, re-rack, clear, save, load, the bot's
// advice) as commands to the server, scenario files, and the physics pane.
#pragma once

#include <array>
#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "client/app/controls.h"
#include "client/app/input.h"
#include "client/app/match_session.h"
#include "game/loaded_table.h"
#include "protocol/practice_request.h"
#include "protocol/shot_request.h"

namespace pool::ui {

/// What a practice key asked for beyond a command: a shot to send, and a line for the notes.
struct PracticeOutcome {
  std::optional<protocol::ShotRequest> shot;  ///< J: the remembered shot, from the table as is
  std::optional<app::SessionNote> note;
};

/// The practice keys and the physics pane of one window. Commands go out one at a time: those
/// a key asked for while the table was busy (a load's layout, then its coefficients) wait here.
class PracticeDesk {
 public:
  /// `scenario_file`: where F5 saves and F6 loads.
  PracticeDesk(const game::LoadedTable& view, std::string scenario_file);

  /// Handles practice key `key` at the session's practice table (nothing elsewhere).
  PracticeOutcome key(app::Key key, app::MatchSession& session, app::Controls& controls);
  /// Ball `id` dragged to `at` (m): the table as `view` shows it with that ball there, as a
  /// layout command (the server refuses a spot the rules do not allow).
  void moveBall(const client::MatchView& view, int id, const Eigen::Vector2d& at);
  /// Sends the next waiting command once the table is free; a refusal to send is a note.
  std::optional<app::SessionNote> step(app::MatchSession& session);
  /// The physics pane (F7) for this frame: sliders of the table's coefficients, Apply and
  /// Standard; the texts it drew go to `texts`.
  void drawPhysicsPane(const client::MatchView& view, std::vector<std::string>& texts);
  bool paneOpen() const { return pane_open_; }

  /// The scenario JSON of the table `view` shows and `shot` (a placement in it puts the cue ball
  /// there first), with the table's coefficients.
  static std::string scenarioOf(const client::MatchView& view, const protocol::ShotRequest& shot,
                                const std::string& table);

 private:
  app::SessionNote save(const app::MatchSession& session) const;
  app::SessionNote load(app::MatchSession& session);
  app::SessionNote advise(const app::MatchSession& session, app::Controls& controls) const;
  void queue(protocol::PracticeRequest request) { waiting_.push_back(std::move(request)); }

  const game::LoadedTable& view_;
  std::string file_;
  std::deque<protocol::PracticeRequest> waiting_;
  bool pane_open_ = false;
  std::optional<protocol::PracticeCoefficients> editing_;  ///< the pane's values, once opened
};

}  // namespace pool::ui
