// Physics-verified pot selection with a look at the next shot.
#include "client/bot/ai/pot_search.h"

#include <array>

namespace pool::bot {
namespace {

/// A speed factor and a tip height (fraction of R) to try on a line, in order.
struct Variant {
  double speed_factor;
  double tip;
};
constexpr std::array<Variant, 5> kVariants{
    {{1.0, 0.0}, {1.0, -0.3}, {1.3, 0.0}, {0.8, 0.2}, {1.5, -0.35}}};

// Worth of a trial for a pot; empty when it fails.
std::optional<double> potValue(const Trial& trial, const TableView& view) {
  if (!trial.judged || trial.loses) return std::nullopt;
  if (trial.wins) return 1000.0;
  if (trial.dead_layout) return std::nullopt;
  if (!trial.verdict.legal() || !trial.potted_call || !trial.verdict.turn_continues) {
    return std::nullopt;
  }
  return 100.0 + 10.0 * shooterChances(trial.after, trial.verdict.next, view);
}

PlannedShot potShot(const PlanContext& context, const PotCandidate& candidate,
                    const Variant& variant) {
  PlannedShot shot = context.blank(ShotKind::Pot);
  const double speed = potSpeed(candidate.line, context.view.spec.params);
  shot.cue = stroke(candidate.line.yaw, speed * variant.speed_factor, variant.tip);
  shot.called_ball = candidate.line.ball;
  shot.called_pocket = context.view.pockets[static_cast<std::size_t>(candidate.line.pocket)].name;
  shot.cue_ball_at = candidate.place;
  return shot;
}

}  // namespace

std::optional<PlannedShot> searchPots(PlanContext& context,
                                      const std::vector<PotCandidate>& candidates) {
  std::optional<PlannedShot> best;
  const std::size_t lines = std::min<std::size_t>(candidates.size(), kMaxLinesVerified);
  for (std::size_t i = 0; i < lines; ++i) {
    for (const Variant& variant : kVariants) {
      PlannedShot shot = potShot(context, candidates[i], variant);
      const auto trial = context.tryShot(shot);
      if (!trial) return best;
      const auto value = potValue(*trial, context.view);
      if (!value) continue;
      shot.value = *value;
      if (!best || shot.value > best->value) best = shot;
      // A winning shot needs no comparison; another variant of a working line rarely pays.
      if (trial->wins) return best;
      break;
    }
  }
  return best;
}

std::vector<PotCandidate> potsFromLie(const PlanContext& context) {
  std::vector<PotCandidate> out;
  const auto cue = ballAt(context.balls, physics::kCueBall);
  if (!cue) return out;
  for (const auto& line : potLines(*cue, context.balls, context.legalBalls(), context.view)) {
    out.push_back(PotCandidate{line, std::nullopt});
  }
  return out;
}

}  // namespace pool::bot
