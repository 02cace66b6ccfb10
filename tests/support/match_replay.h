// Replays a recorded match through the rules engine: every accepted shot's layout before, the
// command's call and placement, the server's events and the layout after are judged again, and
// each verdict must match the server's; the replay's winner is the answer.
#pragma once

#include <algorithm>
#include <sstream>
#include <string>
#include <vector>

#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/table_view.h"
#include "rules/eight_ball.h"
#include "support/match_recorder.h"

namespace pool::client::test {

/// The outcome of a replay.
struct Replay {
  std::string error;  ///< empty: every shot was judged as the server judged it
  int winner = -1;
  int shots = 0;
};

namespace detail {

// The state with the highest (or lowest) revision among those after `shot_number` shots.
inline const MatchView* stateAt(const std::vector<MatchView>& states, std::uint32_t shot_number,
                                bool latest) {
  const MatchView* found = nullptr;
  for (const auto& s : states) {
    if (s.shot_number != shot_number || !(inPlay(s.phase) || s.phase == MatchPhase::Over)) continue;
    if (!found || (latest ? s.revision > found->revision : s.revision < found->revision)) {
      found = &s;
    }
  }
  return found;
}

// The layout after a shot: the server's layout at rest, with the balls the log says went down
// or off the table marked so (the server may have re-spotted them already).
inline std::vector<physics::Ball> afterOf(std::vector<physics::Ball> balls,
                                          const physics::EventLog& events) {
  for (const auto& e : events) {
    for (auto& b : balls) {
      if (b.id != e.ball_a) continue;
      if (e.type == physics::EventType::Pocket) b.state = physics::MotionState::Pocketed;
      if (e.type == physics::EventType::OffTable) b.state = physics::MotionState::OffTable;
    }
  }
  return balls;
}

inline rules::Intent intentOf(const protocol::ShotRequest& command) {
  rules::Intent intent;
  if (command.called_ball)
    intent = rules::Intent::call(*command.called_ball, command.called_pocket);
  intent.safety = command.safety;
  if (command.option == protocol::ShotOption::PlayOn) intent.choice = rules::Choice::PlayOn;
  if (command.option == protocol::ShotOption::BallInHand) intent.choice = rules::Choice::BallInHand;
  return intent;
}

inline std::string compare(const rules::Verdict& v, const ShotReport& r) {
  std::ostringstream why;
  if (v.fouls != r.fouls) why << " fouls differ;";
  if (v.pocketed != r.pocketed) why << " pocketed differ;";
  if (v.turn_continues != r.turn_continues) why << " turn_continues differs;";
  if (v.next_shooter != r.next_shooter)
    why << " next shooter " << v.next_shooter << " vs " << r.next_shooter << ";";
  if (v.game_over != r.game_over || v.winner != r.winner) why << " game over/winner differ;";
  return why.str();
}

}  // namespace detail

/// Replays `match` as `recorder` saw it, on `table`.
inline Replay replayMatch(const MatchRecorder& recorder, const std::string& match,
                          const bot::TableView& table) {
  Replay replay;
  const auto states = recorder.states(match);
  const auto finals = recorder.finals(match);
  const MatchView* start = detail::stateAt(states, 0, true);
  if (!start || start->phase != MatchPhase::Break) {
    replay.error = "no state of the rack before the break";
    return replay;
  }
  rules::GameState game = gameStateOf(*start);
  for (const auto& [n, report] : finals) {
    const std::string at = "shot " + std::to_string(n) + ": ";
    const MatchView* before = detail::stateAt(states, n - 1, true);
    const MatchView* after = detail::stateAt(states, n, false);
    const protocol::ShotRequest* command = recorder.command(match, report.seat, report.seq);
    if (!before || !after || !command) {
      replay.error = at + "missing " + (!command ? "command" : "state");
      return replay;
    }
    Result<rules::Verdict> verdict = Result<rules::Verdict>::fail("");
    if (!protocol::optionShoots(command->option)) {
      const auto choice = command->option == protocol::ShotOption::ReBreak
                              ? rules::Choice::ReBreak
                              : rules::Choice::OpponentReBreaks;
      verdict = rules::applyChoice(game, choice, before->balls, table.context);
    } else {
      rules::Shot shot;
      shot.before = command->cue_ball_at
                        ? bot::withCueBallAt(before->balls, *command->cue_ball_at, table.radius())
                        : before->balls;
      shot.intent = detail::intentOf(*command);
      shot.events = report.events;
      shot.after = detail::afterOf(after->balls, report.events);
      verdict = rules::judgeEightBall(game, shot, table.context);
    }
    if (!verdict) {
      replay.error = at + "the rules refused it: " + verdict.error();
      return replay;
    }
    if (auto diff = detail::compare(*verdict, report); !diff.empty()) {
      replay.error = at + "verdict differs from the server's:" + diff;
      return replay;
    }
    game = verdict->next;
    ++replay.shots;
  }
  replay.winner = game.winner;
  return replay;
}

}  // namespace pool::client::test
