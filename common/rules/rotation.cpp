// The WPA 9-ball and 10-ball referee: the shooter's intent, from a checked shot to a verdict, the
// choices, three fouls in a row.
#include "rules/rotation.h"

#include <algorithm>
#include <string>

#include "rules/respot.h"
#include "rules/rotation_detail.h"

namespace pool::rules {
namespace {

using detail::Judged;

Result<bool> refuse(std::string reason) {
  return Result<bool>::fail(std::move(reason));
}

bool offered(const GameState& state, Choice choice) {
  return std::find(state.options.begin(), state.options.end(), choice) != state.options.end();
}

// A choice given with a shot may only be one the shot starts with (play on, push out).
Result<bool> checkChoice(const GameState& state, const Intent& intent) {
  if (state.options.empty()) {
    if (intent.choice) return refuse("no choice is pending");
    return Result<bool>::ok(true);
  }
  if (!intent.choice) return refuse("choose first: " + describe(state));
  if (!offered(state, *intent.choice))
    return refuse(std::string("choice ") + toString(*intent.choice) + " is not offered");
  if (*intent.choice != Choice::PlayOn && *intent.choice != Choice::PushOut) {
    return refuse(std::string("choice ") + toString(*intent.choice) +
                  " is made without a shot: apply it first");
  }
  return Result<bool>::ok(true);
}

Result<bool> checkCall(const Intent& intent, const std::vector<physics::Ball>& balls,
                       const RotationConfig& config) {
  int id = *intent.ball;
  std::string name = "called ball " + std::to_string(id);
  if (id < 1 || id > rackBall(config.game)) return refuse(name + " is not in this game");
  if (!detail::ballOnTable(id, balls)) return refuse(name + " is not on the table");
  if (!isPocketName(intent.pocket)) return refuse("unknown called pocket '" + intent.pocket + "'");
  return Result<bool>::ok(true);
}

// The state the shot is played from once a choice made with it applies.
GameState stateForShot(const GameState& state, const Intent& intent) {
  GameState st = state;
  if (!intent.choice) return st;
  st.options.clear();
  st.push_out = *intent.choice == Choice::PushOut;
  return st;
}

// The third foul in a row loses the rack; a legal shot clears the shooter's count.
void countFouls(const GameState& state, Verdict& v, std::array<int, kSeats>& fouls_in_row) {
  fouls_in_row = state.fouls_in_row;
  int& mine = fouls_in_row[state.shooter];
  mine = v.legal() ? 0 : mine + 1;
  if (mine >= 3 && !v.game_over) detail::endGame(state, GameEnd::ThreeFouls, v);
}

Verdict finish(const GameState& state, const Shot& shot, Judged judged, const TableContext& table,
               const RotationConfig& config) {
  Verdict& v = judged.verdict;
  std::array<int, kSeats> fouls_in_row{};
  countFouls(state, v, fouls_in_row);
  if (!v.game_over) v.respots = respotBalls(judged.respot_ids, shot.after, table);
  int dry_turns = v.pocketed.empty() ? state.dry_turns + 1 : 0;
  detail::checkStalemate(state, dry_turns, config.stalemate_turns, v);
  v.next = detail::nextState(state, v, dry_turns);
  if (!v.rerack) v.next.fouls_in_row = fouls_in_row;
  return v;
}

}  // namespace

const char* toString(Rotation game) {
  switch (game) {
    case Rotation::NineBall:
      return "9-ball";
    case Rotation::TenBall:
      return "10-ball";
  }
  return "unknown";
}

int rackBall(Rotation game) {
  return game == Rotation::TenBall ? 10 : 9;
}

int lowestBall(const std::vector<physics::Ball>& balls) {
  int lowest = -1;
  for (const auto& b : balls) {
    if (!isObjectBall(b.id) || !physics::onTable(b.state)) continue;
    if (lowest < 0 || b.id < lowest) lowest = b.id;
  }
  return lowest;
}

std::vector<int> rotationFirstBalls(const std::vector<physics::Ball>& balls) {
  int lowest = lowestBall(balls);
  if (lowest < 0) return {};
  return {lowest};
}

Result<bool> checkRotationIntent(const GameState& state, const Intent& intent,
                                 const std::vector<physics::Ball>& balls,
                                 const RotationConfig& config) {
  if (state.phase == Phase::Over) return refuse("the game is over");
  if (auto ok = checkChoice(state, intent); !ok) return ok;
  const GameState st = stateForShot(state, intent);
  // The break and a push-out need no call; whatever was declared is ignored.
  if (st.phase == Phase::Break || st.push_out) return Result<bool>::ok(true);
  if (intent.ball && intent.safety) return refuse("a call and a safety at once");
  if (intent.safety) return Result<bool>::ok(true);
  if (intent.ball) return checkCall(intent, balls, config);
  if (config.game == Rotation::TenBall)
    return refuse("call a ball and a pocket, or declare a safety");
  return Result<bool>::ok(true);
}

Result<Verdict> judgeRotation(const GameState& state, const Shot& shot, const TableContext& table,
                              const RotationConfig& config) {
  if (auto ok = checkRotationIntent(state, shot.intent, shot.before, config); !ok)
    return Result<Verdict>::fail(ok.error());
  GameState st = stateForShot(state, shot.intent);
  if (auto ok = detail::checkCueInHand(st, shot, table); !ok)
    return Result<Verdict>::fail(ok.error());
  if (shot.clock_expired && shot.events.empty())
    return Result<Verdict>::ok(finish(st, shot, detail::timeOut(st), table, config));
  auto facts = distilShot(shot, table.spots.head_string_x);
  if (!facts) return Result<Verdict>::fail(facts.error());
  Judged judged = st.phase == Phase::Break ? detail::judgeRotationBreak(st, shot, *facts, config)
                                           : detail::judgeRotationPlay(st, shot, *facts, config);
  detail::addWatchdogRemovals(*facts, judged);
  return Result<Verdict>::ok(finish(st, shot, std::move(judged), table, config));
}

Result<Verdict> applyRotationChoice(const GameState& state, Choice choice) {
  if (!offered(state, choice)) {
    return Result<Verdict>::fail(std::string("choice ") + toString(choice) + " is not offered");
  }
  switch (choice) {
    case Choice::PlayOn:
      return Result<Verdict>::ok(detail::playOnVerdict(state, state.ball_in_hand));
    case Choice::PushOut: {
      Verdict v = detail::playOnVerdict(state, state.ball_in_hand);
      v.next.push_out = true;
      return Result<Verdict>::ok(v);
    }
    case Choice::PassBack: {
      Verdict v;
      detail::passTurn(state, BallInHand::None, v);
      v.next = state;
      v.next.options.clear();
      v.next.shooter = v.next_shooter;
      v.next.ball_in_hand = BallInHand::None;
      return Result<Verdict>::ok(v);
    }
    case Choice::ReBreak:
      return Result<Verdict>::ok(detail::rerackVerdict(state.shooter));
    case Choice::OpponentReBreaks:
      return Result<Verdict>::ok(detail::rerackVerdict(opponentOf(state.shooter)));
    case Choice::BallInHand:
    case Choice::RespotEight:
      break;
  }
  return Result<Verdict>::fail(std::string("choice ") + toString(choice) +
                               " is not part of 9-ball or 10-ball");
}

}  // namespace pool::rules
