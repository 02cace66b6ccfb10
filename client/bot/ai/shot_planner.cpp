// Turn planning: options, the break, pots from the lie or from hand, safeties, the fallback.
#include "client/bot/ai/shot_planner.h"

#include <algorithm>

#include "client/bot/ai/break_shot.h"
#include "client/bot/ai/carom_search.h"
#include "client/bot/ai/cue_placement.h"
#include "client/bot/ai/plan_context.h"
#include "client/bot/ai/pot_search.h"
#include "client/bot/ai/safety_shot.h"

namespace pool::bot {
namespace {

constexpr int kCaromTrials = 2000;  // physics trials a three-cushion turn

bool offered(const std::vector<rules::Choice>& options, rules::Choice choice) {
  return std::find(options.begin(), options.end(), choice) != options.end();
}

// The state the shot is played in once `choice` applies (it only changes the ball in hand).
rules::GameState stateAfterChoice(rules::GameState state, std::optional<rules::Choice> choice) {
  if (!choice) return state;
  if (*choice == rules::Choice::BallInHand)
    state.ball_in_hand = rules::BallInHand::BehindHeadString;
  state.push_out = *choice == rules::Choice::PushOut;
  state.free_ball = *choice == rules::Choice::FreeBall;
  state.options.clear();
  return state;
}

// Below these chances of a clear pot the bot would rather not shoot the table as it lies.
constexpr double kPushOutBelow = 1e-9;  // no pot line at all for the lowest ball
constexpr double kPassBackBelow = 0.3;

// 9-/10-ball: push out when the lowest ball has no pot line; after a push-out (or a missed call)
// play on only from a table that offers a reasonable pot, else hand it back.
std::optional<rules::Choice> rotationChoice(const std::vector<physics::Ball>& balls,
                                            const rules::GameState& state, const TableView& view) {
  rules::GameState as_is = state;
  as_is.options.clear();
  const double chances = shooterChances(balls, as_is, view);
  if (offered(state.options, rules::Choice::PushOut)) {
    return chances < kPushOutBelow ? rules::Choice::PushOut : rules::Choice::PlayOn;
  }
  if (offered(state.options, rules::Choice::PassBack)) {
    return chances < kPassBackBelow ? rules::Choice::PassBack : rules::Choice::PlayOn;
  }
  return std::nullopt;
}

PlannedShot planPlay(PlanContext& context) {
  const bool in_hand = context.play_state.ball_in_hand != rules::BallInHand::None;
  const auto pots = in_hand ? potsFromHand(context) : potsFromLie(context);
  if (auto pot = searchPots(context, pots)) return *pot;
  const auto spots = in_hand ? restingSpots(context) : std::vector<Vec2>{};
  if (auto safety = searchSafety(context, spots)) return *safety;
  return fallbackShot(context, spots.empty() ? std::nullopt : std::optional<Vec2>(spots.front()));
}

}  // namespace

std::optional<rules::Choice> chooseOption(const std::vector<rules::Choice>& options) {
  if (options.empty()) return std::nullopt;
  // Snooker: a free ball is the table as it lies with one more ball to play at.
  for (rules::Choice c : {rules::Choice::BallInHand, rules::Choice::FreeBall, rules::Choice::PlayOn,
                          rules::Choice::ReBreak, rules::Choice::OpponentReBreaks}) {
    if (offered(options, c)) return c;
  }
  return options.front();
}

ShotPlanner::ShotPlanner(const TableView& view, PlannerOptions options)
    : view_(view), options_(options), verifier_(view) {}

PlannedShot ShotPlanner::plan(const std::vector<physics::Ball>& balls,
                              const rules::GameState& state) {
  if (view_.rules.game == rules::Game::ThreeCushion) {
    // A carom stroke is cheap to try (three balls): the search looks far wider than a pot's
    // (bot_bench, BM_CaromInnings: 0.75 points an inning at 320 trials, 2.05 at 2000 with 16
    // samples, under the olympiad noise).
    return planCarom(verifier_, balls, state,
                     {std::max(options_.max_runs, kCaromTrials), options_.noise, options_.samples});
  }
  auto choice = chooseOption(state.options);
  // A free ball is taken whenever offered (it only adds a ball to play at); otherwise a table
  // without a pot is handed back.
  if (choice != rules::Choice::FreeBall) {
    if (auto rotation = rotationChoice(balls, state, view_)) choice = rotation;
  }
  PlanContext context{view_,
                      verifier_,
                      balls,
                      state,
                      stateAfterChoice(state, choice),
                      choice,
                      options_.max_runs,
                      options_.noise,
                      options_.samples,
                      options_.leave_weight,
                      options_.look_ahead,
                      options_.breadth};
  if (choice && *choice != rules::Choice::PlayOn && *choice != rules::Choice::BallInHand &&
      *choice != rules::Choice::PushOut && *choice != rules::Choice::FreeBall) {
    // Re-racking answers carry no stroke (a re-spotted 8 is never chosen: re-breaking is simpler).
    return context.blank(ShotKind::Choice);
  }
  if (state.phase == rules::Phase::Break) return planBreak(context);
  return planPlay(context);
}

}  // namespace pool::bot
