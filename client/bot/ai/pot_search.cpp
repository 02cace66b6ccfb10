// Physics-verified pot selection with a look at the next shot.
#include "client/bot/ai/pot_search.h"

#include <algorithm>
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

// What a foul costs in a pot's value (a clean pot with a hopeless leave is worth 100).
constexpr double kFoulCost = 40.0;

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

// What one played (noisy) try of a pot is worth: the exact value when it works; a miss leaves
// the table to the opponent (worth nothing), a foul gives them the cue ball in hand, a loss is the
// game.
double playedValue(const Trial& trial, const TableView& view) {
  if (auto value = potValue(trial, view)) return *value;
  if (!trial.judged) return 0.0;
  if (trial.loses) return -1000.0;
  return trial.verdict.legal() ? 0.0 : -kFoulCost;
}

// The shortlist sampled under the bot's noise: the pots with the best exact values.
constexpr std::size_t kShortlist = 6;

}  // namespace

std::optional<PlannedShot> searchPots(PlanContext& context,
                                      const std::vector<PotCandidate>& candidates) {
  const bool sampling = context.samples > 0;
  std::vector<PlannedShot> working;
  const std::size_t lines = std::min<std::size_t>(candidates.size(), kMaxLinesVerified);
  for (std::size_t i = 0; i < lines; ++i) {
    for (const Variant& variant : kVariants) {
      PlannedShot shot = potShot(context, candidates[i], variant);
      const auto trial = context.tryShot(shot);
      if (!trial) break;
      const auto value = potValue(*trial, context.view);
      if (!value) continue;
      shot.value = *value;
      // A winning shot needs no comparison; without sampling, another variant of a working line
      // rarely pays.
      if (trial->wins && !sampling) return shot;
      working.push_back(shot);
      if (!sampling) break;
    }
  }
  std::stable_sort(working.begin(), working.end(),
                   [](const PlannedShot& a, const PlannedShot& b) { return a.value > b.value; });
  if (!sampling || working.size() <= 1) {
    if (working.empty()) return std::nullopt;
    return working.front();
  }
  // Each shortlisted pot played as the bot plays: the one worth most on average wins. The exact
  // order stands for any the budget leaves unsampled.
  working.resize(std::min(working.size(), kShortlist));
  std::optional<PlannedShot> best;
  for (PlannedShot& shot : working) {
    double sum = 0.0;
    int made = 0, played = 0;
    for (int k = 0; k < context.samples; ++k) {
      const auto trial = context.tryNoisy(shot);
      if (!trial) break;
      ++played;
      sum += playedValue(*trial, context.view);
      made += trial->potted_call || trial->wins ? 1 : 0;
    }
    if (played < context.samples) break;
    shot.value = sum / played;
    shot.success = static_cast<double>(made) / played;
    if (!best || shot.value > best->value) best = shot;
  }
  return best ? best : std::optional<PlannedShot>(working.front());
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
