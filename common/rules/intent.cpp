// The 8-ball shooter's intent: which balls may be hit first and called, and the checks before a
// shot.
#include <algorithm>
#include <string>

#include "rules/eight_ball.h"
#include "rules/table_context.h"
#include "rules/verdict_steps.h"

namespace pool::rules {
namespace {

template <class T>
bool contains(const std::vector<T>& items, const T& item) {
  return std::find(items.begin(), items.end(), item) != items.end();
}

Check<> refuse(const char* code, std::string reason) {
  return Check<>::refuse(code, std::move(reason));
}

std::string optionList(const std::vector<Choice>& options) {
  std::string text;
  for (Choice c : options) text += (text.empty() ? "" : ", ") + std::string(toString(c));
  return text;
}

// A choice given with a shot may only be one that leaves the balls as they are.
Check<> checkChoice(const GameState& state, const Intent& intent) {
  if (state.options.empty()) {
    if (intent.choice) return refuse("no_choice_pending", "no choice is pending");
    return Check<>::pass();
  }
  if (!intent.choice) return refuse("choose_first", "choose first: " + optionList(state.options));
  if (!contains(state.options, *intent.choice)) {
    return refuse("choice_not_offered", std::string("choice ") + toString(*intent.choice) +
                                            " is not offered (" + optionList(state.options) + ")");
  }
  if (*intent.choice != Choice::PlayOn && *intent.choice != Choice::BallInHand) {
    return refuse("choice_needs_no_shot", std::string("choice ") + toString(*intent.choice) +
                                              " changes the table: apply it before the shot");
  }
  return Check<>::pass();
}

Check<> checkCall(const GameState& state, const Intent& intent,
                  const std::vector<physics::Ball>& balls) {
  int id = *intent.ball;
  std::string name = "called ball " + std::to_string(id);
  if (!isObjectBall(id)) return refuse("not_object_ball", name + " is not an object ball");
  if (!detail::ballOnTable(id, balls))
    return refuse("ball_not_on_table", name + " is not on the table");
  if (!isPocketName(intent.pocket))
    return refuse("unknown_pocket", "unknown called pocket '" + intent.pocket + "'");
  bool callable =
      id == kEightBall ? onTheEight(state, balls) : contains(legalFirstBalls(state, balls), id);
  if (!callable) return refuse("not_shooters_ball", name + " is not the shooter's to call");
  return Check<>::pass();
}

}  // namespace

const char* toString(CallMode mode) {
  switch (mode) {
    case CallMode::Standard:
      return "standard";
    case CallMode::Casual:
      return "casual";
  }
  return "unknown";
}

bool onTheEight(const GameState& state, const std::vector<physics::Ball>& balls) {
  if (state.phase != Phase::Assigned) return false;
  Group mine = state.groups[state.shooter];
  return std::none_of(balls.begin(), balls.end(), [mine](const physics::Ball& b) {
    return physics::onTable(b.state) && groupOf(b.id) == mine;
  });
}

std::vector<int> legalFirstBalls(const GameState& state, const std::vector<physics::Ball>& balls) {
  bool eight_next = onTheEight(state, balls);
  std::vector<int> ids;
  for (const auto& b : balls) {
    if (!physics::onTable(b.state) || !isObjectBall(b.id)) continue;
    bool legal = state.phase == Phase::Break ||
                 (state.phase == Phase::Open && b.id != kEightBall) ||
                 (state.phase == Phase::Assigned &&
                  (eight_next ? b.id == kEightBall : groupOf(b.id) == state.groups[state.shooter]));
    if (legal) ids.push_back(b.id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

Check<> checkIntent(const GameState& state, const Intent& intent,
                    const std::vector<physics::Ball>& balls, const EightBallConfig& config) {
  if (state.phase == Phase::Over) return refuse("game_over", "the game is over");
  if (auto ok = checkChoice(state, intent); !ok) return ok;
  // The break needs no call; whatever was declared is ignored.
  if (state.phase == Phase::Break) return Check<>::pass();
  if (intent.ball && intent.safety) return refuse("call_and_safety", "a call and a safety at once");
  if (intent.safety) return Check<>::pass();
  if (intent.ball) return checkCall(state, intent, balls);
  if (config.calls == CallMode::Standard)
    return refuse("no_call", "call a ball and a pocket, or declare a safety");
  if (onTheEight(state, balls)) return refuse("eight_needs_call", "the 8 needs a called pocket");
  return Check<>::pass();
}

}  // namespace pool::rules
