// Physics-verified pot selection with a look at the next shot.
#include "client/bot/ai/pot_search.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include "client/bot/ai/bank_shot.h"
#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/leave_value.h"
#include "client/bot/ai/throw_aim.h"
#include "rules/game_rules.h"

namespace pool::bot {
namespace {

/// A speed factor, a tip height and a side offset (fractions of R) to try on a line, in order: the
/// strokes of every level first, then finer steps of speed and spin for a level that tries more,
/// then six strokes with side spin (running or reverse English, 0.3 R) each way
/// (PotBreadth::variants).
struct Variant {
  double speed_factor;
  double tip;
  double side = 0.0;
};
constexpr std::array<Variant, kMaxVariants> kVariants{{
    {1.0, 0.0},        {1.0, -0.3},      {1.3, 0.0},       {0.8, 0.2},       {1.5, -0.35},
    {0.75, 0.0},       {0.75, -0.4},     {1.0, 0.35},      {1.3, -0.4},      {1.3, 0.35},
    {1.8, 0.0},        {1.8, -0.4},      {0.65, 0.0},      {0.65, 0.3},      {0.65, -0.3},
    {0.9, -0.15},      {0.9, 0.15},      {1.15, -0.2},     {1.15, 0.2},      {1.15, 0.45},
    {1.15, -0.5},      {1.5, 0.0},       {1.5, 0.2},       {1.5, -0.55},     {2.1, 0.0},
    {2.1, -0.5},       {2.1, 0.3},       {2.5, 0.0},       {2.5, -0.5},      {0.85, -0.55},
    {1.0, -0.55},      {1.3, -0.6},      {0.9, 0.45},      {1.7, 0.4},       {2.5, 0.3},
    {1.8, -0.6},       {1.0, 0.0, 0.3},  {1.0, 0.0, -0.3}, {1.3, -0.3, 0.3}, {1.3, -0.3, -0.3},
    {0.8, 0.2, 0.3},   {0.8, 0.2, -0.3}, {1.5, 0.2, 0.3},  {1.5, 0.2, -0.3}, {1.0, -0.4, 0.3},
    {1.0, -0.4, -0.3}, {2.0, 0.0, 0.3},  {2.0, 0.0, -0.3},
}};

// Worth of a trial for a pot; empty when it fails.
std::optional<double> potValue(const Trial& trial, const PlanContext& context) {
  if (!trial.judged || trial.loses) return std::nullopt;
  if (trial.wins) return 1000.0;
  if (trial.dead_layout) return std::nullopt;
  if (!trial.verdict.legal() || !trial.potted_call || !trial.verdict.turn_continues) {
    return std::nullopt;
  }
  return context.keptTurnWorth(trial);
}

PlannedShot potShot(const PlanContext& context, const PotCandidate& candidate,
                    const Variant& variant) {
  PlannedShot shot = context.blank(ShotKind::Pot);
  const double speed = potSpeed(candidate.line, context.view.spec.params);
  shot.cue = stroke(candidate.line.yaw, speed * variant.speed_factor, variant.tip);
  shot.cue.tip_side = variant.side;
  shot.called_ball = candidate.line.ball;
  shot.called_pocket = context.view.pockets[static_cast<std::size_t>(candidate.line.pocket)].name;
  shot.nominate = context.play_state.ball_on == rules::kOnColour || context.play_state.free_ball;
  shot.cue_ball_at = candidate.place;
  return shot;
}

// What one played (noisy) try of a pot is worth: the exact value when it works; a miss leaves
// the table to the opponent (worth nothing), a foul gives them the cue ball in hand, a loss is the
// game.
double playedValue(const Trial& trial, const PlanContext& context) {
  if (auto value = potValue(trial, context)) return *value;
  if (!trial.judged) return 0.0;
  if (trial.loses) return -1000.0;
  return trial.verdict.legal() ? 0.0 : -kFoulCost;
}

// At most two variants (speed, spin and side) of one line go on the shortlist sampled under the
// bot's noise.
constexpr std::size_t kVariantsShortlisted = 2;

}  // namespace

std::optional<PlannedShot> searchPots(PlanContext& context,
                                      const std::vector<PotCandidate>& candidates) {
  const bool sampling = context.samples > 0;
  std::vector<PlannedShot> working;
  const std::size_t lines =
      std::min<std::size_t>(candidates.size(), static_cast<std::size_t>(context.breadth.lines));
  const auto variants = std::span(kVariants).first(
      static_cast<std::size_t>(std::clamp(context.breadth.variants, 1, kMaxVariants)));
  for (std::size_t i = 0; i < lines; ++i) {
    std::vector<PlannedShot> line;  // this line's working variants
    for (const Variant& variant : variants) {
      PlannedShot shot = potShot(context, candidates[i], variant);
      aimForThrow(context, shot, candidates[i].line);
      const auto trial = context.tryShot(shot);
      if (!trial) break;
      const auto value = potValue(*trial, context);
      if (!value) continue;
      shot.value = *value;
      // A winning shot needs no comparison; without sampling, another variant of a working line
      // rarely pays.
      if (trial->wins && !sampling) return shot;
      line.push_back(shot);
      if (!sampling) break;
    }
    // The shortlist holds every line's best variants, not one line's many.
    std::stable_sort(line.begin(), line.end(),
                     [](const PlannedShot& a, const PlannedShot& b) { return a.value > b.value; });
    if (line.size() > kVariantsShortlisted) line.resize(kVariantsShortlisted);
    working.insert(working.end(), line.begin(), line.end());
  }
  std::stable_sort(working.begin(), working.end(),
                   [](const PlannedShot& a, const PlannedShot& b) { return a.value > b.value; });
  if (working.empty()) return std::nullopt;
  if (!sampling) return working.front();
  // Each shortlisted pot played as the bot plays: the one worth most on average wins. The exact
  // order stands for any the budget leaves unsampled.
  working.resize(std::min(working.size(), static_cast<std::size_t>(context.breadth.shortlist)));
  std::optional<PlannedShot> best;
  for (PlannedShot& shot : working) {
    int made = 0;  // made cleanly, keeping the turn (or won)
    const auto mean = context.meanOfNoisy(shot, context.samples, [&](const Trial& trial) {
      made += potValue(trial, context) ? 1 : 0;
      return playedValue(trial, context);
    });
    if (!mean) break;
    shot.value = *mean;
    shot.success = static_cast<double>(made) / context.samples;
    if (!best || shot.value > best->value) best = shot;
  }
  return best ? best : std::optional<PlannedShot>(working.front());
}

std::vector<PotCandidate> potsFromLie(const PlanContext& context) {
  std::vector<PotCandidate> out;
  const auto cue = ballAt(context.balls, physics::kCueBall);
  if (!cue) return out;
  const auto legal = context.legalBalls();
  for (const auto& line : potLines(*cue, context.balls, legal, context.view)) {
    out.push_back(PotCandidate{line, std::nullopt});
  }
  // Banks after every direct line: tried when the direct ones leave room in the search.
  if (context.breadth.banks) {
    for (const auto& line : bankLines(*cue, context.balls, legal, context.view)) {
      out.push_back(PotCandidate{line, std::nullopt});
    }
  }
  return out;
}

}  // namespace pool::bot
