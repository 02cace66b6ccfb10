// The WPA 8-ball referee: its steps of the judging pipeline, from a checked shot to a verdict.
#include "rules/eight_ball.h"

#include "rules/eight_ball_steps.h"
#include "rules/referee.h"

namespace pool::rules {
namespace {

class EightBallReferee final : public detail::Referee {
 public:
  explicit EightBallReferee(const EightBallConfig& config) : config_(config) {}

  Check<> checkIntent(const GameState& state, const Intent& intent,
                      const std::vector<physics::Ball>& balls) const override {
    return rules::checkIntent(state, intent, balls, config_);
  }

  // A choice answered with the shot (play on, or ball in hand) applies before it.
  GameState stateForShot(const GameState& state, const Intent& intent) const override {
    GameState st = state;
    if (!intent.choice) return st;
    if (*intent.choice == Choice::BallInHand) st.ball_in_hand = BallInHand::BehindHeadString;
    st.options.clear();
    return st;
  }

  detail::Judged judgeBreak(const GameState& state, const Shot& shot, const ShotFacts& facts,
                            const TableContext&) const override {
    return detail::judgeBreak(state, shot, facts);
  }

  detail::Judged judgePlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                           const TableContext& table) const override {
    return detail::judgePlay(state, shot, facts, table, config_);
  }

  bool threeFoulsLose() const override { return false; }  // no such rule in WPA 8-ball
  int stalemateTurns() const override { return config_.stalemate_turns; }

 private:
  EightBallConfig config_;
};

}  // namespace

Result<Verdict> judgeEightBall(const GameState& state, const Shot& shot, const TableContext& table,
                               const EightBallConfig& config) {
  return detail::judgeWith(EightBallReferee(config), state, shot, table);
}

}  // namespace pool::rules
