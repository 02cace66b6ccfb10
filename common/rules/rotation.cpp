// The WPA 9-ball and 10-ball referee: the shooter's intent, from a checked shot to a verdict, the
// choices, three fouls in a row.
#include "rules/rotation.h"

#include <algorithm>
#include <string>

#include "rules/referee.h"
#include "rules/rotation_steps.h"

namespace pool::rules {
namespace {

Check<> refuse(const char* code, std::string reason) {
  return Check<>::refuse(code, std::move(reason));
}

bool offered(const GameState& state, Choice choice) {
  return std::find(state.options.begin(), state.options.end(), choice) != state.options.end();
}

// A choice given with a shot may only be one the shot starts with (play on, push out).
Check<> checkChoice(const GameState& state, const Intent& intent) {
  if (state.options.empty()) {
    if (intent.choice) return refuse("no_choice_pending", "no choice is pending");
    return Check<>::pass();
  }
  if (!intent.choice) return refuse("choose_first", "choose first: " + describe(state));
  if (!offered(state, *intent.choice))
    return refuse("choice_not_offered",
                  std::string("choice ") + toString(*intent.choice) + " is not offered");
  if (*intent.choice != Choice::PlayOn && *intent.choice != Choice::PushOut) {
    return refuse("choice_needs_no_shot", std::string("choice ") + toString(*intent.choice) +
                                              " is made without a shot: apply it first");
  }
  return Check<>::pass();
}

Check<> checkCall(const Intent& intent, const std::vector<physics::Ball>& balls,
                  const RotationConfig& config) {
  int id = *intent.ball;
  std::string name = "called ball " + std::to_string(id);
  if (id < 1 || id > rackBall(config.game))
    return refuse("ball_not_in_game", name + " is not in this game");
  if (!detail::ballOnTable(id, balls))
    return refuse("ball_not_on_table", name + " is not on the table");
  if (!isPocketName(intent.pocket))
    return refuse("unknown_pocket", "unknown called pocket '" + intent.pocket + "'");
  return Check<>::pass();
}

// The state the shot is played from once a choice made with it applies.
GameState stateAfterChoice(const GameState& state, const Intent& intent) {
  GameState st = state;
  if (!intent.choice) return st;
  st.options.clear();
  st.push_out = *intent.choice == Choice::PushOut;
  return st;
}

class RotationReferee final : public detail::Referee {
 public:
  explicit RotationReferee(const RotationConfig& config) : config_(config) {}

  Check<> checkIntent(const GameState& state, const Intent& intent,
                      const std::vector<physics::Ball>& balls) const override {
    return checkRotationIntent(state, intent, balls, config_);
  }

  GameState stateForShot(const GameState& state, const Intent& intent) const override {
    return stateAfterChoice(state, intent);
  }

  detail::Judged judgeBreak(const GameState& state, const Shot& shot, const ShotFacts& facts,
                            const TableContext&) const override {
    return detail::judgeRotationBreak(state, shot, facts, config_);
  }

  detail::Judged judgePlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                           const TableContext&) const override {
    return detail::judgeRotationPlay(state, shot, facts, config_);
  }

  bool threeFoulsLose() const override { return true; }
  int stalemateTurns() const override { return config_.stalemate_turns; }

 private:
  RotationConfig config_;
};

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

Check<> checkRotationIntent(const GameState& state, const Intent& intent,
                            const std::vector<physics::Ball>& balls, const RotationConfig& config) {
  if (state.phase == Phase::Over) return refuse("game_over", "the game is over");
  if (auto ok = checkChoice(state, intent); !ok) return ok;
  const GameState st = stateAfterChoice(state, intent);
  // The break and a push-out need no call; whatever was declared is ignored.
  if (st.phase == Phase::Break || st.push_out) return Check<>::pass();
  if (intent.ball && intent.safety) return refuse("call_and_safety", "a call and a safety at once");
  if (intent.safety) return Check<>::pass();
  if (intent.ball) return checkCall(intent, balls, config);
  if (config.game == Rotation::TenBall)
    return refuse("no_call", "call a ball and a pocket, or declare a safety");
  return Check<>::pass();
}

Result<Verdict> judgeRotation(const GameState& state, const Shot& shot, const TableContext& table,
                              const RotationConfig& config) {
  return detail::judgeWith(RotationReferee(config), state, shot, table);
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
    case Choice::FreeBall:
    case Choice::Replace:
      break;
  }
  return Result<Verdict>::fail(std::string("choice ") + toString(choice) +
                               " is not part of 9-ball or 10-ball");
}

}  // namespace pool::rules
