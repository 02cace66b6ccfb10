// The heads-up display (Dear ImGui): players by name, turn, groups, balls left, fouls, ball in
// hand, the shot's parameters with the power bar and the tip-offset ball, the call; a banner with
// the last shot's story, the match log, the rules' choices in sentences, the game-over screen and
// the help overlay. Panes are anchored to the window's corners and sized to it.
#pragma once

#include <deque>
#include <optional>
#include <string>
#include <vector>

#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/app/settings.h"
#include "client/app/shot_story.h"
#include "client/net/match_types.h"
#include "protocol/shot_request.h"

namespace pool::ui {

/// What the HUD shows.
struct HudInput {
  const client::MatchView* view = nullptr;
  std::string match;
  bool spectating = false;
  std::vector<int> local_seats;
  int local_shooter = -1;  ///< the seat aiming at this screen; -1: none
  bool in_motion = false;
  const app::Controls* controls = nullptr;
  std::string placement_problem;  ///< why the cue ball cannot go where it is; empty: fine
  std::string last_verdict;
  const std::deque<app::SessionNote>* notes = nullptr;
  std::string banner;                            ///< the last shot's story (app::shotStory)
  const std::deque<std::string>* log = nullptr;  ///< every shot's story, oldest first
  bool help = false;                             ///< the help overlay (F1)
  /// The panes (Tab): when false only a question asked (concede, game over) and a line saying
  /// how to bring them back are drawn.
  bool panes = true;
  /// The players' names (remembered after a player leaves); empty: read from `view`.
  std::optional<app::SeatNames> names;
  app::Settings settings;      ///< as they are now (shown with the help)
  std::string settings_note;   ///< where they are kept, or why they are not
  bool can_concede = false;    ///< a player at this screen may concede the rack in play
  bool concede_asked = false;  ///< the concession waits for the player's yes or no
  bool can_replay = false;     ///< a last shot is kept and the balls are at rest
  bool replaying = false;      ///< the instant replay is showing
  /// The other shooter's live aim (as drawn, smoothed), while it arrives.
  std::optional<app::FollowedAim> live_aim;
  /// The last shot played from this screen (shown while it runs, instead of the reset aim).
  std::optional<protocol::ShotRequest> last_shot;
};

/// What the player clicked.
struct HudActions {
  std::optional<protocol::ShotOption> option;  ///< an answer to the rules' pending choice
  bool rematch = false;
  bool leave = false;
  bool visit_room = false;                ///< the winner goes to the Magic Eight Ball room
  bool new_game = false;                  ///< leave this table for a free one
  bool concede = false;                   ///< asks to concede the rack (a question first)
  std::optional<bool> concede_answer;     ///< yes or no to conceding
  std::optional<double> replay;           ///< replay the last shot at this speed (1: real)
  std::optional<app::Settings> settings;  ///< the player changed a setting
  std::vector<std::string> texts;         ///< every text the HUD drew this frame (tests read them)
};

/// The HUD's text scale (ImGui's FontGlobalScale) for a framebuffer `height` pixels high.
float hudScale(int height);

/// Draws the HUD windows for this frame (between ImGui::NewFrame and ImGui::Render).
HudActions drawHud(const HudInput& input);

/// The tip-offset widget: the cue ball seen from behind, the miscue circle and the tip.
void drawTipWidget(double tip_side, double tip_height, double miscue_limit);

}  // namespace pool::ui
