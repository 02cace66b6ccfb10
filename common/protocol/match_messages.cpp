// The rules' view of a published match state, and which shot results use a sequence number up.
#include "protocol/match_messages.h"

namespace pool::protocol {

bool inPlay(MatchPhase phase) {
  return phase == MatchPhase::Break || phase == MatchPhase::Open || phase == MatchPhase::Assigned;
}

rules::GameState gameStateOf(const MatchView& view) {
  rules::GameState state;
  switch (view.phase) {
    case MatchPhase::Break:
      state.phase = rules::Phase::Break;
      break;
    case MatchPhase::Open:
      state.phase = rules::Phase::Open;
      break;
    case MatchPhase::Assigned:
      state.phase = rules::Phase::Assigned;
      break;
    default:
      state.phase = rules::Phase::Over;
      break;
  }
  state.shooter = view.shooter == 1 ? 1 : 0;
  state.breaker = view.breaker == 1 ? 1 : 0;
  state.groups = {view.seats[0].group, view.seats[1].group};
  state.ball_in_hand = view.ball_in_hand;
  state.options = view.options;
  state.winner = view.winner;
  state.end = view.end;
  state.fouls_in_row = {view.seats[0].fouls_in_row, view.seats[1].fouls_in_row};
  state.points = {view.seats[0].points, view.seats[1].points};
  state.innings = {view.seats[0].innings, view.seats[1].innings};
  state.high_run = {view.seats[0].high_run, view.seats[1].high_run};
  state.run = view.run;
  state.ball_on = view.ball_on;
  state.free_ball = view.free_ball;
  state.misses = {view.seats[0].misses, view.seats[1].misses};
  return state;
}

bool ShotReport::usesUpSequence() const {
  return accepted || protocol::refusedAfterSignature(reject_reason);
}

}  // namespace pool::protocol
