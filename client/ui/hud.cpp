// HUD panels.
#include "client/ui/hud.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

#include "client/app/key_help.h"
#include "client/app/scoreboard.h"
#include "client/app/shot_story.h"
#include "client/app/spoken.h"
#include "rules/rotation.h"

namespace pool::ui {
namespace {

constexpr float kMargin = 10.0f;
const ImVec4 kProblem(1.0f, 0.4f, 0.3f, 1.0f);
const ImVec4 kBannerFoul(1.0f, 0.75f, 0.35f, 1.0f);

double degrees(double rad) {
  return rad * 180.0 / std::numbers::pi;
}

std::string fixed(double value, int decimals, bool sign = false) {
  char text[32];
  std::snprintf(text, sizeof text, sign ? "%+.*f" : "%.*f", decimals, value);
  return text;
}

/// Draws text and keeps it for the frame's record.
class Say {
 public:
  explicit Say(HudActions& out) : out_(out) {}
  void text(const std::string& s) {
    out_.texts.push_back(s);
    ImGui::TextUnformatted(s.c_str());
  }
  void wrapped(const std::string& s) {
    out_.texts.push_back(s);
    ImGui::TextWrapped("%s", s.c_str());
  }
  void coloured(const ImVec4& colour, const std::string& s) {
    out_.texts.push_back(s);
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s", s.c_str());
    ImGui::PopStyleColor();
  }
  bool button(const std::string& label) {
    out_.texts.push_back(label);
    return ImGui::Button(label.c_str());
  }
  bool radio(const std::string& label, bool on) {
    out_.texts.push_back(label);
    return ImGui::RadioButton(label.c_str(), on);
  }
  HudActions& out() { return out_; }

 private:
  HudActions& out_;
};

ImVec2 screenSize() {
  return ImGui::GetMainViewport()->WorkSize;
}

/// Pane widths in pixels grow with the text (ImGui's FontGlobalScale, set from the window).
float px(float pixels) {
  return pixels * ImGui::GetIO().FontGlobalScale;
}

/// The next window at `pivot` of the screen (0,0 top-left … 1,1 bottom-right), at most `max_w` ×
/// `max_h` of the screen, never moved by the player and never off screen.
void anchor(ImVec2 pivot, float max_w, float max_h, float width = 0.0f) {
  const ImVec2 size = screenSize();
  const ImVec2 pos(kMargin + pivot.x * (size.x - 2 * kMargin),
                   kMargin + pivot.y * (size.y - 2 * kMargin));
  ImGui::SetNextWindowPos(pos, ImGuiCond_Always, pivot);
  const float w = std::min(width > 0 ? width : max_w * size.x, size.x - 2 * kMargin);
  ImGui::SetNextWindowSizeConstraints(ImVec2(width > 0 ? w : 0.0f, 0.0f),
                                      ImVec2(w, max_h * size.y));
}

constexpr ImGuiWindowFlags kPane =
    ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse;
/// The panes that stay up in play: the player may drag them by the title (their places are kept
/// in the settings) and collapse them to it.
constexpr ImGuiWindowFlags kStandingPane = ImGuiWindowFlags_AlwaysAutoResize;

/// Begins standing pane `title` (settings key `key`): where the player left it, else at its
/// anchor (`pivot`, sizes as anchor()); while the player drags it, where the drag has it; on the
/// frame the drag ends, its new place goes out with the settings.
void beginStandingPane(Say& say, const HudInput& in, const char* title, const std::string& key,
                       ImVec2 pivot, float max_w, float max_h, float width) {
  const ImVec2 size = screenSize();
  ImGuiWindow* window = ImGui::FindWindowByName(title);
  const bool dragging = window != nullptr && GImGui->MovingWindow == window;
  const auto kept = in.settings.pane_places.find(key);
  anchor(pivot, max_w, max_h, width);  // the size limits, and the anchor unless placed below
  if (dragging) {
    ImGui::SetNextWindowPos(window->Pos, ImGuiCond_Always);
  } else if (window != nullptr && ImGui::IsMouseReleased(ImGuiMouseButton_Left) &&
             GImGui->ActiveIdPreviousFrame == window->MoveId) {
    // A drag of this pane that just ended leaves it where it was last drawn, if that is not where
    // it is kept: the player's new place for it. (A click released elsewhere moves nothing.)
    const ImVec2 at = window->Pos;
    const ImVec2 expected =
        kept != in.settings.pane_places.end()
            ? ImVec2(static_cast<float>(kept->second[0]) * size.x,
                     static_cast<float>(kept->second[1]) * size.y)
            : ImVec2(kMargin + pivot.x * (size.x - 2 * kMargin) - pivot.x * window->Size.x,
                     kMargin + pivot.y * (size.y - 2 * kMargin) - pivot.y * window->Size.y);
    if (std::abs(at.x - expected.x) > 1.0f || std::abs(at.y - expected.y) > 1.0f) {
      app::Settings changed = say.out().settings ? *say.out().settings : in.settings;
      changed.pane_places[key] = {std::clamp(static_cast<double>(at.x / size.x), 0.0, 1.0),
                                  std::clamp(static_cast<double>(at.y / size.y), 0.0, 1.0)};
      say.out().settings = changed;
      ImGui::SetNextWindowPos(at, ImGuiCond_Always);
    } else if (kept != in.settings.pane_places.end()) {
      ImGui::SetNextWindowPos(expected, ImGuiCond_Always);
    }
  } else if (kept != in.settings.pane_places.end()) {
    // Kept inside the window: at least its title's corner on screen.
    const float x = std::clamp(static_cast<float>(kept->second[0]) * size.x, 0.0f, size.x - 60.0f);
    const float y = std::clamp(static_cast<float>(kept->second[1]) * size.y, 0.0f, size.y - 30.0f);
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
  }
  ImGui::Begin(title, nullptr, kStandingPane);
}

app::SeatNames namesOf(const HudInput& in) {
  return in.names ? *in.names : app::seatNames(in.view);
}

bool localSeat(const HudInput& in, int seat) {
  return std::find(in.local_seats.begin(), in.local_seats.end(), seat) != in.local_seats.end();
}

void seatLines(Say& say, const client::MatchView& view, const HudInput& in,
               const app::SeatNames& names) {
  for (int s = 0; s < 2; ++s) {
    const auto& seat = view.seats[static_cast<std::size_t>(s)];
    const bool turn = view.shooter == s && client::inPlay(view.phase);
    std::string line = std::string(turn ? "> " : "  ") +
                       (seat.name.empty() ? "(a free seat)" : names[static_cast<std::size_t>(s)]);
    if (seat.name.empty() && view.phase == client::MatchPhase::Over) {
      line = "  " + names[static_cast<std::size_t>(s)] + " (left)";
    }
    if (localSeat(in, s)) line += " (you)";
    if (!seat.name.empty() && !seat.connected) line += " (away)";
    say.text(line);
    std::string detail = "    ";
    if (view.settings.game == rules::Game::ThreeCushion) {
      // A carom score: points, innings and the high run (UMB's scoreboard).
      detail += std::to_string(seat.points) + (seat.points == 1 ? " point, " : " points, ") +
                std::to_string(seat.innings) + (seat.innings == 1 ? " inning, " : " innings, ") +
                "high run " + std::to_string(seat.high_run);
      say.wrapped(detail);
      continue;
    }
    if (view.settings.game == rules::Game::Snooker) {
      say.wrapped(detail + app::snookerSeatLine(seat));
      continue;
    }
    // Groups and balls left are 8-ball's; in 9- and 10-ball both players shoot the lowest ball.
    if (view.settings.game == rules::Game::EightBall) {
      detail += seat.group == rules::Group::None ? "no group yet"
                                                 : app::spoken(rules::toString(seat.group));
      detail += ", " + std::to_string(seat.balls_left) + " left, ";
    }
    detail += std::to_string(seat.fouls) + (seat.fouls == 1 ? " foul, " : " fouls, ") +
              std::to_string(seat.racks_won) + (seat.racks_won == 1 ? " rack won" : " racks won");
    say.wrapped(detail);
  }
  if (view.settings.game == rules::Game::Snooker) {
    for (const std::string& line : app::snookerLines(view, names)) say.wrapped("  " + line);
  } else if (view.settings.game == rules::Game::ThreeCushion && client::inPlay(view.phase)) {
    say.text(std::string("  ") + (view.cue_ball == 1 ? "the yellow" : "the white") + " to strike" +
             (view.run > 0 ? ", run " + std::to_string(view.run) : ""));
  } else if (view.settings.game != rules::Game::EightBall && client::inPlay(view.phase)) {
    const int lowest = rules::lowestBall(view.balls);
    if (lowest > 0) say.text("  ball on: the " + std::to_string(lowest));
  }
}

// The shot clock as a bar, counted down from the state's arrival; red, with a word, near the end.
void clockBar(const client::MatchView& v) {
  if (v.shot_clock < 0.0 || v.shot_clock_total <= 0.0) return;
  static std::uint32_t seen_revision = 0;
  static double seen_at = 0.0;
  if (v.revision != seen_revision) {
    seen_revision = v.revision;
    seen_at = ImGui::GetTime();
  }
  const double left = std::max(0.0, v.shot_clock - (ImGui::GetTime() - seen_at));
  const bool warning = left <= v.settings.warningAt();
  if (warning) ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.9f, 0.2f, 0.1f, 1.0f));
  char text[32];
  std::snprintf(text, sizeof text, "%.0f s%s", std::ceil(left), warning ? ", time!" : "");
  ImGui::ProgressBar(static_cast<float>(left / v.shot_clock_total), ImVec2(220, 0), text);
  if (warning) ImGui::PopStyleColor();
}

void matchPanel(Say& say, const HudInput& in) {
  beginStandingPane(say, in, "Match", "match", ImVec2(0, 0), 0.32f, 0.45f,
                    std::min(screenSize().x * 0.32f, px(340.0f)));
  say.text(in.match + (in.spectating ? " (watching)" : ""));

  if (!in.view) {
    say.text("waiting for the match state...");
    ImGui::End();
    return;
  }
  const auto& v = *in.view;
  const app::SeatNames names = namesOf(in);
  say.text(app::phaseLine(v));
  seatLines(say, v, in, names);
  if (client::inPlay(v.phase) && v.shooter >= 0) {
    const std::string& who = names[static_cast<std::size_t>(v.shooter)];
    std::string turn = v.settings.practice ? "shoot when you like" : who + " to shoot";
    const std::string where = app::inHandWhere(v.ball_in_hand);
    if (!where.empty()) turn += ", cue ball in hand " + where;
    say.wrapped(turn);
  }
  if (v.settings.practice) {
    say.text("practice table, " + app::spoken(rules::toString(v.settings.game)) + " rack, " +
             std::to_string(v.undo_depth) + " to undo");
    if (!v.standard_physics) {
      say.coloured(kBannerFoul, "not a standard table: its coefficients were changed (F7)");
    }
  } else {
    say.wrapped(app::raceLine(v));
  }
  if (v.shot_clock >= 0) {
    say.out().texts.push_back("shot clock: " + fixed(v.shot_clock, 0) + " s");
    clockBar(v);
  }
  if (in.in_motion) say.text("balls moving");
  if (in.replaying) {
    say.text("Replay of the last shot");
  } else if (in.can_replay) {
    if (say.button("Replay the last shot (I)")) say.out().replay = 1.0;
    ImGui::SameLine();
    if (say.button("Slow")) say.out().replay = 0.4;
  }
  if (in.can_concede && !in.concede_asked &&
      say.button("Concede the " + app::rackWord(v.settings.game) + " (Q)")) {
    say.out().concede = true;
  }
  if (ImGui::SmallButton("Leave to the lobby")) say.out().leave = true;
  say.out().texts.push_back("Leave to the lobby");
  ImGui::End();
}

void bannerPanel(Say& say, const HudInput& in) {
  if (in.banner.empty() || in.in_motion) return;
  anchor(ImVec2(0.5f, 0), 0.34f, 0.3f, std::min(screenSize().x * 0.34f, px(560.0f)));
  ImGui::Begin("Last shot", nullptr, kPane | ImGuiWindowFlags_NoTitleBar);
  const bool foul = in.banner.rfind("Foul", 0) == 0;
  say.coloured(foul ? kBannerFoul : ImVec4(1, 1, 1, 1), in.banner);
  ImGui::End();
}

void choicePanel(Say& say, const HudInput& in) {
  if (!in.view || in.local_shooter < 0 || in.view->options.empty()) return;
  const app::SeatNames names = namesOf(in);
  const std::string& other = names[static_cast<std::size_t>(1 - in.local_shooter)];
  anchor(ImVec2(0.5f, 1), 0.4f, 0.4f);
  ImGui::Begin("Your choice", nullptr, kPane);
  say.wrapped(names[static_cast<std::size_t>(in.local_shooter)] +
              ", the rules let you choose before you shoot:");
  const auto chosen = in.controls->aim().option;
  const rules::Game game = in.view->settings.game;
  int number = 0;
  for (const rules::Choice c : in.view->options) {
    const protocol::ShotOption option = protocol::optionOf(c);
    const std::string label = std::to_string(++number) + ": " + app::choiceSentence(c, other, game);
    if (say.radio(label, chosen == option)) say.out().option = option;
  }
  const std::string keys =
      number == 1 ? "Key 1 chooses too. " : "Keys 1 to " + std::to_string(number) + " choose too. ";
  say.wrapped(keys + (game == rules::Game::Snooker
                          ? "Playing from here or a free ball goes with your next shot; making " +
                                other + " play again (the balls put back or not) is sent at once."
                          : "Playing on or taking the cue ball goes with your next shot; a new "
                            "rack is sent at once."));
  ImGui::End();
}

void callLine(Say& say, const app::Controls& c, const client::MatchView* v) {
  const app::AimState& aim = c.aim();
  if (c.pickedBall()) {
    say.text("the " + std::to_string(*c.pickedBall()) + " picked: click the pocket to call");
  }
  const bool snooker = v && v->settings.game == rules::Game::Snooker;
  if (aim.call.safety) {
    say.text("call: a safety (K drops it)");
  } else if (snooker && aim.call.ball) {
    say.wrapped("nominated: the " + app::snookerBallName(*aim.call.ball) +
                " (a click on it again drops it)");
  } else if (aim.call.ball) {
    std::string line = "call: the " + std::to_string(*aim.call.ball) + " in the " +
                       app::spoken(aim.call.pocket) +
                       (aim.call.by_player ? "" : " (C: next pocket; or click a ball, a pocket)");
    say.wrapped(line);
    if (*aim.call.ball == rules::kEightBall) say.coloured(kProblem, "the 8: check the pocket");
  } else if (!v || v->phase == client::MatchPhase::Break) {
    say.text("call: none needed on the break");
  } else if (v->settings.game == rules::Game::NineBall) {
    say.text("call: none needed in 9-ball");
  } else if (snooker) {
    say.wrapped(
        "call: no pocket in snooker (a colour or a free ball: click it to nominate it, else the "
        "one hit first)");
  } else {
    say.wrapped("call: none yet (aim at a ball, or click a ball and then a pocket)");
  }
}

/// The other shooter's cue in numbers: heading, elevation, tip and the power drawn.
void liveAimLines(Say& say, const app::AimState& aim, const protocol::CommandLimits& limits) {
  say.text("their aim " + fixed(degrees(aim.yaw), 2) + " deg   cue elevation " +
           fixed(degrees(aim.elevation), 1) + " deg");
  say.text("tip side " + fixed(aim.tip_side, 2, true) + " R   height " +
           fixed(aim.tip_height, 2, true) + " R");
  say.text("cue drawn back for " + fixed(app::cueSpeedOf(aim.power, limits), 2) + " m/s");
  ImGui::ProgressBar(static_cast<float>(aim.power), ImVec2(px(220), 0), "their power");
}

/// The shot this screen played last, in numbers.
void lastShotLines(Say& say, const protocol::ShotRequest& shot) {
  say.wrapped("your shot: aim " + fixed(degrees(shot.cue.yaw), 2) + " deg, cue elevation " +
              fixed(degrees(shot.cue.elevation), 1) + " deg, cue speed " +
              fixed(shot.cue.speed, 2) + " m/s");
  say.text("tip side " + fixed(shot.cue.tip_side, 2, true) + " R   height " +
           fixed(shot.cue.tip_height, 2, true) + " R");
}

void shotPanel(Say& say, const HudInput& in) {
  const app::Controls& c = *in.controls;
  const app::AimState& aim = c.aim();
  beginStandingPane(say, in, "Shot", "shot", ImVec2(0, 1), 0.32f, 0.5f,
                    std::min(screenSize().x * 0.32f, px(340.0f)));
  const app::SeatNames names = namesOf(in);
  if (in.local_shooter >= 0) {
    say.wrapped(names[static_cast<std::size_t>(in.local_shooter)] +
                ", your turn: aim, then hold Space, Ctrl + drag or Enter");
  } else {
    if (in.view && client::inPlay(in.view->phase) && in.view->shooter >= 0) {
      say.text(names[static_cast<std::size_t>(in.view->shooter)] +
               (in.in_motion ? " has shot" : " is at the table"));
    } else if (in.view && in.view->phase == client::MatchPhase::Over) {
      say.text("the game is over");
    } else if (in.view && in.view->phase == client::MatchPhase::Lobby) {
      say.text("waiting for an opponent to sit down");
    } else {
      say.text("watching");
    }
    // The shooter's aim as their live aim shows it; without one, no numbers rather than numbers
    // that are not theirs.
    if (in.live_aim && in.view && in.live_aim->seat == in.view->shooter && !in.in_motion) {
      liveAimLines(say, in.live_aim->aim, c.limits());
    }
    // Our own shot on its way: what was played, not the aim the controls reset for the next turn.
    if (localSeat(in, in.view ? in.view->shooter : -1) && in.last_shot) {
      lastShotLines(say, *in.last_shot);
      if (!c.strokeNote().empty()) say.wrapped(c.strokeNote());
    }
    say.text("F1: keys");
    ImGui::End();
    return;
  }
  say.text("aim " + fixed(degrees(aim.yaw), 2) + " deg   cue elevation " +
           fixed(degrees(aim.elevation), 1) + " deg");
  say.text("tip side " + fixed(aim.tip_side, 2, true) + " R   height " +
           fixed(aim.tip_height, 2, true) + " R");
  if (c.stroking() && aim.stroke_back) {
    say.wrapped("stroke: cue drawn back " + fixed(*aim.stroke_back * 100.0, 0) +
                " cm (push up through the ball)");
  } else {
    say.text("cue speed " + fixed(app::cueSpeedOf(aim.power, c.limits()), 2) + " m/s (- / +)");
  }
  ImGui::ProgressBar(static_cast<float>(aim.power), ImVec2(px(220), 0),
                     c.charging() ? "charging" : "power");
  if (!c.strokeNote().empty()) say.wrapped(c.strokeNote());
  drawTipWidget(aim.tip_side, aim.tip_height, c.limits().miscue_limit);
  callLine(say, c, in.view);
  if (aim.cue_ball_at) {
    say.text("cue ball in hand: drag it");
    if (!in.placement_problem.empty()) {
      say.coloured(kProblem, "it cannot go there: " + app::spokenText(in.placement_problem));
    }
  }
  const app::Toggles& t = c.toggles();
  say.text(std::string("G aim line ") + (t.aim_line ? "on" : "off") + "   V arrows " +
           (t.vectors ? "on" : "off") + "   F1 keys");
  ImGui::End();
}

void logPanel(Say& say, const HudInput& in) {
  const bool log = in.log && !in.log->empty();
  const bool notes = in.notes && !in.notes->empty();
  if (!log && !notes) return;
  const ImVec2 size = screenSize();
  beginStandingPane(say, in, "Match log", "log", ImVec2(1, 0), 0.3f, 0.42f,
                    std::min(size.x * 0.3f, px(460.0f)));
  if (log) {
    const float height = std::min(size.y * 0.25f, px(220.0f));
    ImGui::BeginChild("shots", ImVec2(0, height), true);
    for (const auto& line : *in.log) say.wrapped(line);
    if (ImGui::GetScrollY() >= ImGui::GetScrollMaxY() - 1) ImGui::SetScrollHereY(1.0f);
    ImGui::EndChild();
  }
  if (notes) {
    for (const auto& n : *in.notes) {
      if (n.problem) {
        say.coloured(kProblem, app::spokenText(n.text));
      } else {
        say.wrapped(app::spokenText(n.text));
      }
    }
  }
  ImGui::End();
}

void concedePanel(Say& say, const HudInput& in) {
  if (!in.concede_asked || !in.view) return;
  const app::SeatNames names = namesOf(in);
  int mine = in.local_seats.size() == 1 ? in.local_seats.front() : in.view->shooter;
  if (mine != 0 && mine != 1) return;
  const std::string& other = names[static_cast<std::size_t>(1 - mine)];
  const std::string rack = app::rackWord(in.view->settings.game);
  anchor(ImVec2(0.5f, 0.5f), 0.5f, 0.4f, std::min(screenSize().x * 0.45f, px(480.0f)));
  ImGui::Begin("Concede the rack?", nullptr, kPane);
  say.wrapped(names[static_cast<std::size_t>(mine)] + ", concede this " + rack + " to " + other +
              "? " + other + " wins it; the race goes on, or ends if that was the last " + rack +
              ".");
  if (say.button("Yes, concede (Y)")) say.out().concede_answer = true;
  ImGui::SameLine();
  if (say.button("No, play on (Esc)")) say.out().concede_answer = false;
  ImGui::End();
}

void gameOverPanel(Say& say, const HudInput& in) {
  if (!in.view || in.view->phase != client::MatchPhase::Over) return;
  const auto& v = *in.view;
  const app::SeatNames names = namesOf(in);
  anchor(ImVec2(0.5f, 0.5f), 0.5f, 0.6f, std::min(screenSize().x * 0.45f, px(520.0f)));
  ImGui::Begin("Game over", nullptr, kPane);
  if (v.winner == 0 || v.winner == 1) {
    const std::string& winner = names[static_cast<std::size_t>(v.winner)];
    say.wrapped(winner + (localSeat(in, v.winner) ? " (you) wins" : " wins") + ": " +
                app::endReason(v.end) + ".");
  } else {
    say.wrapped("The game is over.");
  }
  say.text((v.settings.game == rules::Game::Snooker ? "Frames: " : "Racks: ") + names[0] + " " +
           std::to_string(v.seats[0].racks_won) + ", " + names[1] + " " +
           std::to_string(v.seats[1].racks_won));
  if (!in.local_seats.empty()) {
    // A rematch needs both players; one who left cannot accept it.
    int gone = -1;
    for (int s = 0; s < 2; ++s) {
      const auto& seat = v.seats[static_cast<std::size_t>(s)];
      if (!localSeat(in, s) && (seat.name.empty() || !seat.connected)) gone = s;
    }
    if (gone >= 0) {
      say.coloured(kProblem, names[static_cast<std::size_t>(gone)] +
                                 " has left the table: a rematch needs both players. Start a "
                                 "new game at a free table instead.");
    } else if (say.button("Rematch (R)")) {
      say.out().rematch = true;
    }
    if (say.button("New game (N)")) say.out().new_game = true;
    const bool won = localSeat(in, v.winner);
    if (won && say.button("Visit the Magic Eight Ball room")) say.out().visit_room = true;
  }
  if (say.button("Leave to the lobby")) say.out().leave = true;
  ImGui::End();
}

void settingsLines(Say& say, const HudInput& in) {
  ImGui::Separator();
  say.text("Settings");
  app::Settings s = in.settings;
  bool changed = false;
  auto check = [&](const std::string& label, bool& value) {
    say.out().texts.push_back(label);
    changed = ImGui::Checkbox(label.c_str(), &value) || changed;
  };
  check("Aim line and ghost ball (G)", s.aim_line);
  check("Direction arrows (V)", s.vectors);
  check("Full screen (F11)", s.full_screen);
  check("Follow the cue ball while the balls run", s.follow_cue);
  float volume = static_cast<float>(s.volume);
  say.out().texts.push_back("Volume (from the next start)");
  if (ImGui::SliderFloat("Volume (from the next start)", &volume, 0.0f, 1.0f, "%.2f")) {
    s.volume = volume;
    changed = true;
  }
  float stroke = static_cast<float>(s.stroke_mm);
  say.out().texts.push_back("Mouse stroke: mm of cue a pixel");
  if (ImGui::SliderFloat("Mouse stroke: mm of cue a pixel", &stroke, 0.2f, 5.0f, "%.2f")) {
    s.stroke_mm = stroke;
    changed = true;
  }
  say.text("Quality (at once)");
  for (const char* q : {"auto", "high", "full", "light"}) {
    ImGui::SameLine();
    const std::string label = std::string(q) + "##quality";
    say.out().texts.push_back(q);
    if (ImGui::RadioButton(label.c_str(), s.quality == q) && s.quality != q) {
      s.quality = q;
      changed = true;
    }
  }
  say.wrapped("auto: light under software OpenGL (the scene at 0.6 of the resolution), else full");
  if (!s.pane_places.empty()) {
    say.out().texts.push_back("Panes back to their places");
    if (ImGui::Button("Panes back to their places")) {
      s.pane_places.clear();
      changed = true;
    }
  }
  if (!in.settings_note.empty()) say.wrapped(in.settings_note);
  if (changed) say.out().settings = s;
}

/// With the panes hidden: one small line in the top-left corner, no background.
void hiddenLine(Say& say) {
  anchor(ImVec2(0.0f, 0.0f), 0.5f, 0.1f);
  ImGui::Begin("HUD hidden", nullptr,
               kPane | ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoBackground |
                   ImGuiWindowFlags_NoInputs);
  say.text("Tab: show the panes");
  ImGui::End();
}

void helpPanel(Say& say, const HudInput& in) {
  anchor(ImVec2(0.5f, 0.5f), 0.9f, 0.9f, std::min(screenSize().x * 0.9f, px(760.0f)));
  ImGui::SetNextWindowBgAlpha(1.0f);  // over the table and the other panes: nothing shows through
  ImGui::Begin("Keys (F1 closes)", nullptr, kPane);
  if (ImGui::BeginTable("keys", 3, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    for (const auto& k : app::keyHelp()) {
      ImGui::TableNextRow();
      ImGui::TableSetColumnIndex(0);
      say.text(std::string(k.when));
      ImGui::TableSetColumnIndex(1);
      say.text(std::string(k.keys));
      ImGui::TableSetColumnIndex(2);
      say.wrapped(std::string(k.does));
    }
    ImGui::EndTable();
  }
  settingsLines(say, in);
  ImGui::End();
}

}  // namespace

void drawTipWidget(double tip_side, double tip_height, double miscue_limit) {
  const float size = 90.0f * ImGui::GetIO().FontGlobalScale, radius = size * 0.45f;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const ImVec2 centre(origin.x + size / 2, origin.y + size / 2);
  ImDrawList* draw = ImGui::GetWindowDrawList();
  draw->AddCircleFilled(centre, radius, IM_COL32(240, 240, 230, 255), 48);
  draw->AddCircle(centre, radius * static_cast<float>(miscue_limit), IM_COL32(200, 60, 60, 255),
                  48);
  draw->AddLine(ImVec2(centre.x - radius, centre.y), ImVec2(centre.x + radius, centre.y),
                IM_COL32(160, 160, 160, 255));
  draw->AddLine(ImVec2(centre.x, centre.y - radius), ImVec2(centre.x, centre.y + radius),
                IM_COL32(160, 160, 160, 255));
  const ImVec2 tip(centre.x + radius * static_cast<float>(tip_side),
                   centre.y - radius * static_cast<float>(tip_height));
  draw->AddCircleFilled(tip, 5.0f, IM_COL32(30, 80, 220, 255), 16);
  ImGui::Dummy(ImVec2(size, size));
}

float hudScale(int height) {
  return std::clamp(static_cast<float>(height) / 800.0f, 1.0f, 2.0f);
}

HudActions drawHud(const HudInput& input) {
  HudActions actions;
  Say say(actions);
  if (!input.panes) {
    hiddenLine(say);
    gameOverPanel(say, input);
    concedePanel(say, input);
    return actions;
  }
  matchPanel(say, input);
  bannerPanel(say, input);
  choicePanel(say, input);
  if (input.controls) shotPanel(say, input);
  logPanel(say, input);
  gameOverPanel(say, input);
  concedePanel(say, input);
  if (input.help) helpPanel(say, input);
  return actions;
}

}  // namespace pool::ui
