// Replays a recorded match through the rules engine: every accepted shot's layout before, the
// command's call and placement, the server's events and the layout after are judged again, and
// each verdict must match the server's; the replay's winner is the answer.
#pragma once

#include <algorithm>
#include <array>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

#include "client/bot/ai/shot_verifier.h"
#include "client/bot/ai/table_view.h"
#include "rules/game_rules.h"
#include "support/match_recorder.h"

namespace pool::client::test {

/// The outcome of a replay.
struct Replay {
  std::string error;  ///< empty: every shot was judged as the server judged it
  int winner = -1;
  int shots = 0;
  int racks = 0;  ///< racks judged to their end
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
  if (command.option == protocol::ShotOption::PushOut) intent.choice = rules::Choice::PushOut;
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

/// Every final answer of `match` in the order the server gave them: shots, choices without a
/// shot (which keep the shot number of the shot before) and shot clock expiries.
inline std::vector<ShotReport> finalsInOrder(const MatchRecorder& recorder,
                                             const std::string& match) {
  std::vector<ShotReport> out;
  for (const auto& r : recorder.reports()) {
    if (r.match != match || !r.final()) continue;
    const bool seen = std::any_of(out.begin(), out.end(), [&](const ShotReport& o) {
      return o.seat == r.seat && o.seq == r.seq && o.shot_number == r.shot_number &&
             o.verdict_text == r.verdict_text;
    });
    if (!seen) out.push_back(r);
  }
  return out;
}

/// Replays `match` as `recorder` saw it, on `table`, by the rules of the match's game; a race
/// goes on with the server's next rack after each rack won, and its winner is the answer.
inline Replay replayMatch(const MatchRecorder& recorder, const std::string& match,
                          const bot::TableView& table) {
  Replay replay;
  const auto states = recorder.states(match);
  const MatchView* start = detail::stateAt(states, 0, true);
  if (!start || start->phase != MatchPhase::Break) {
    replay.error = "no state of the rack before the break";
    return replay;
  }
  const rules::GameRules game_rules{start->settings.game, {}, {start->settings.points}};
  const int race_to = start->settings.race_to;
  std::array<int, 2> racks{0, 0};
  rules::GameState game = gameStateOf(*start);
  for (const ShotReport& report : finalsInOrder(recorder, match)) {
    const std::uint32_t n = report.shot_number;
    const std::string at = "shot " + std::to_string(n) + ": ";
    const protocol::ShotRequest* command = recorder.command(match, report.seat, report.seq);
    const bool time_out = report.seq == 0 && !command;
    const bool shoots = !time_out && command && protocol::optionShoots(command->option);
    const MatchView* before = detail::stateAt(states, shoots ? n - 1 : n, shoots);
    const MatchView* after = detail::stateAt(states, n, false);
    if (!before || !after || (!command && !time_out)) {
      replay.error = at + "missing " + (!command ? "command" : "state");
      return replay;
    }
    Result<rules::Verdict> verdict = Result<rules::Verdict>::fail("");
    if (time_out) {
      rules::Shot shot{before->balls, rules::Intent::safe(), {}, before->balls, true};
      verdict = rules::judgeShot(game_rules, game, shot, table.context);
    } else if (!shoots) {
      const auto choice = protocol::choiceOf(command->option);
      if (!choice) {
        replay.error = at + "a command without a shot answers no choice";
        return replay;
      }
      verdict = rules::applyChoiceFor(game_rules, game, *choice, before->balls, table.context);
    } else {
      rules::Shot shot;
      shot.before = command->cue_ball_at
                        ? bot::withCueBallAt(before->balls, *command->cue_ball_at, table.radius())
                        : before->balls;
      shot.intent = detail::intentOf(*command);
      shot.events = report.events;
      // A shot that ended a rack of a race is followed at once by the next rack's layout: its
      // own end is the table at the strike with the balls the log took off marked so.
      const bool next_rack = after->rack != before->rack;
      shot.after = detail::afterOf(next_rack ? shot.before : after->balls, report.events);
      verdict = rules::judgeShot(game_rules, game, shot, table.context);
    }
    if (!verdict) {
      replay.error = at + "the rules refused it: " + verdict.error();
      return replay;
    }
    if (auto diff = detail::compare(*verdict, report); !diff.empty()) {
      replay.error = at + "verdict differs from the server's:" + diff + " (replayed '" +
                     rules::describe(*verdict) + "', the server's '" + report.verdict_text + "')";
      return replay;
    }
    game = verdict->next;
    if (shoots) ++replay.shots;
    if (verdict->game_over && verdict->winner >= 0) {
      const int won = ++racks[static_cast<std::size_t>(verdict->winner)];
      if (won >= race_to) {
        replay.winner = verdict->winner;
        ++replay.racks;
        return replay;
      }
      // The race goes on: the server racked again; its state says who breaks.
      const MatchView* next_rack = detail::stateAt(states, n, true);
      if (!next_rack || next_rack->phase != MatchPhase::Break) {
        replay.error = at + "no state of the next rack";
        return replay;
      }
      game = gameStateOf(*next_rack);
      ++replay.racks;
    }
  }
  replay.winner = game.winner;
  return replay;
}

}  // namespace pool::client::test
