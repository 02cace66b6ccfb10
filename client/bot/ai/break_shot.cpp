// Break placement and aim from the measured breaks, checked in the physics.
#include "client/bot/ai/break_shot.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

#include "client/bot/ai/cue_placement.h"
#include "client/bot/ai/safety_shot.h"

namespace pool::bot {
namespace {

// How far behind the head string the cue ball sits (the rules want it strictly behind), m.
constexpr double kSetback = 0.01;

// bot_bench BM_BreakGrid on wpa-9ft, 200 hand racks each (seeds 1000–1199), the olympiad
// noise: the share of breaks that pot a ball / are legal / keep the turn. Mirror images are one
// break here (planBreak tries both sides). The 9-ball strokes are the best of the grid's 864 (6
// places, 9 aims, 4 speeds, 4 tips); for 8- and 10-ball the best of its first 64 (4 places, 4
// aims, 2 speeds, 2 tips) stay: the larger grid's winners did no better out of sample
// (BM_BotBreak, seeds 5000–5199).
constexpr std::array kEightBall{
    BreakStroke{0.55, 0.0, 11.0, 0.2},   // 84.5 / 90.0 / 78.5 %
    BreakStroke{0.40, 0.3, 11.0, -0.1},  // 80.5 / 87.5 / 76.5 %
    BreakStroke{0.55, 0.0, 11.0, -0.1},  // 76.5 / 87.0 / 73.5 %
    BreakStroke{0.00, 0.0, 11.0, 0.2},   // 73.5 / 93.0 / 70.0 %
};
constexpr std::array kNineBall{
    BreakStroke{0.40, -0.15, 11.0, 0.2},  // 66.0 / 92.5 / 60.5 %
    BreakStroke{0.30, 0.0, 11.0, 0.4},    // 62.5 / 90.0 / 56.0 %
    BreakStroke{0.10, 0.3, 11.0, 0.2},    // 64.0 / 92.5 / 55.0 %
    BreakStroke{0.00, -0.45, 11.0, 0.2},  // 64.0 / 89.0 / 54.5 %
};
constexpr std::array kTenBall{
    BreakStroke{0.40, 0.3, 9.0, -0.1},  // 84.0 / 93.5 / 83.0 %
    BreakStroke{0.55, 0.0, 9.0, -0.1},  // 81.0 / 93.0 / 80.5 %
    BreakStroke{0.55, 0.3, 9.0, -0.1},  // 81.0 / 86.5 / 79.5 %
    BreakStroke{0.20, 0.6, 11.0, 0.2},  // 75.5 / 86.5 / 74.0 %
};

double breakValue(const Trial& trial) {
  if (!trial.judged || trial.loses || trial.dead_layout) return -1.0;
  double value = trial.verdict.legal() ? 50.0 : 0.0;
  value += 10.0 * static_cast<double>(trial.verdict.pocketed.size());
  if (trial.verdict.turn_continues) value += 30.0;
  return value;
}

// Legal, and so with the cue ball still on the table: a scratch or a cue ball off the table is a
// foul in every game (rules::leavingFouls).
bool legalBreak(const Trial& trial) {
  return trial.judged && !trial.loses && !trial.dead_layout && trial.verdict.legal();
}

// Break strokes played a sampling level's way: each tried under its own noise, worth the turn
// kept with its leave (as a pot is), a foul its cost; the best on average is played.
constexpr int kBreakSamples = 16;  // at most, each (a break moves every ball: a dear trial)

double breakWorth(const Trial& trial, const PlanContext& context) {
  if (!trial.judged || trial.dead_layout) return 0.0;
  if (trial.loses) return -1000.0;
  if (trial.wins) return 1000.0;
  if (!trial.verdict.legal()) return -kFoulCost;
  return trial.verdict.turn_continues ? context.keptTurnWorth(trial) : 0.0;
}

PlannedShot sampledBreak(PlanContext& context, const std::vector<PlannedShot>& legal) {
  const int samples = std::min(context.samples, kBreakSamples);
  std::optional<PlannedShot> best;
  for (PlannedShot shot : legal) {
    const auto mean = context.meanOfNoisy(
        shot, samples, [&](const Trial& trial) { return breakWorth(trial, context); });
    if (!mean) break;
    shot.value = *mean;
    if (!best || shot.value > best->value) best = shot;
  }
  return best ? *best : legal.front();
}

}  // namespace

std::span<const BreakStroke> measuredBreaks(rules::Game game) {
  switch (game) {
    case rules::Game::EightBall:
      return kEightBall;
    case rules::Game::NineBall:
      return kNineBall;
    case rules::Game::TenBall:
      return kTenBall;
    case rules::Game::ThreeCushion:
      return {};  // no rack to break: the carom planner plays the opening
    case rules::Game::Snooker:
      return {};  // the break-off is a safety (planSnookerBreak)
  }
  return kEightBall;
}

bool looksRacked(const TableView& view, const std::vector<physics::Ball>& balls) {
  const Vec2 foot = view.context.spots.foot_spot;
  const double r = view.radius();
  constexpr double kSpare = 3e-3;  // m: a hand rack's gaps (up to 1 mm over four rows)
  const double depth = 4.0 * std::sqrt(3.0) * r;  // apex row to the fifth row's centres
  int racked = 0;
  for (const auto& b : balls) {
    if (b.id == physics::kCueBall || !physics::onTable(b.state)) continue;
    const Vec2 p = b.pos.head<2>() - foot;
    // Inside the triangle of the five rows' centres, grown by the spare.
    const double half_width_here = std::max(0.0, p.x()) / std::sqrt(3.0);
    if (p.x() < -kSpare || p.x() > depth + kSpare || std::abs(p.y()) > half_width_here + kSpare) {
      return false;
    }
    ++racked;
  }
  return racked >= 9;
}

Vec2 apexBall(const TableView& view, const std::vector<physics::Ball>& balls) {
  const Vec2 foot = view.context.spots.foot_spot;
  Vec2 apex = foot;
  double best = std::numeric_limits<double>::infinity();
  for (const auto& b : balls) {
    if (b.id == physics::kCueBall || !physics::onTable(b.state)) continue;
    const double d = (b.pos.head<2>() - foot).norm();
    if (d < best) {
      best = d;
      apex = b.pos.head<2>();
    }
  }
  return apex;
}

PlannedShot breakShot(const TableView& view, const Vec2& apex, const BreakStroke& plan, int side) {
  PlannedShot shot;
  shot.kind = ShotKind::Break;
  const Vec2 at(view.headStringX() - kSetback, side * plan.y);
  shot.cue_ball_at = at;
  const Vec2 to = apex - at;
  // Square to the line of aim, toward the cue ball's side (+y for side +1; the apex lies ahead).
  const Vec2 across = side * Vec2(-to.y(), to.x()).normalized();
  const Vec2 aim = apex + plan.offset * view.radius() * across;
  shot.cue = stroke(std::atan2(aim.y() - at.y(), aim.x() - at.x()), plan.speed, plan.tip);
  return shot;
}

// Snooker's break-off (a safety, as every player plays it): from the D halfway between the
// brown and the yellow, a thin contact on the outside of the back row's end red on that side,
// the cue ball off the top and side cushions back toward baulk. The strokes are tried in the
// physics: the first legal one that brings the cue ball back behind the blue, else the legal one
// ending farthest back.
std::optional<PlannedShot> snookerBreakOff(PlanContext& context) {
  const auto& d = context.view.context.snooker;
  if (!d) return std::nullopt;
  const double r = context.view.radius();
  const Vec2 at = d->brown + 0.5 * (d->yellow - d->brown);
  std::optional<Vec2> end_red;
  for (const auto& b : context.balls) {
    if (!rules::isRed(b.id) || !physics::onTable(b.state)) continue;
    const Vec2 p = b.pos.head<2>();
    // The back row's (largest x) ball nearest the cue ball's side.
    if (!end_red || p.x() > end_red->x() + r ||
        (std::abs(p.x() - end_red->x()) <= r && p.y() < end_red->y()))
      end_red = p;
  }
  if (!end_red) return std::nullopt;
  const Vec2 to = (*end_red - at).normalized();
  const Vec2 outside(to.y(), -to.x());  // square to the line, away from the pack (−y)
  std::optional<PlannedShot> best;
  double best_back = std::numeric_limits<double>::infinity();
  for (double thin : {0.92, 0.85, 0.97}) {
    for (double speed : {2.6, 3.0, 2.2}) {
      PlannedShot shot = context.blank(ShotKind::Break);
      shot.cue_ball_at = at;
      const Vec2 aim = *end_red + thin * 2.0 * r * outside;
      shot.cue = stroke(std::atan2(aim.y() - at.y(), aim.x() - at.x()), speed, 0.0);
      shot.cue.tip_side = -0.3;  // running side off the top cushion
      if (!placementLegal(context, at)) return std::nullopt;
      const auto trial = context.tryShot(shot);
      if (!trial) return best;
      if (!legalBreak(*trial)) continue;
      shot.value = breakValue(*trial);
      if (trial->cue_end.x() < 0.0) return shot;
      if (trial->cue_end.x() < best_back) {
        best_back = trial->cue_end.x();
        best = shot;
      }
    }
  }
  return best;
}

PlannedShot planBreak(PlanContext& context) {
  if (context.view.rules.game == rules::Game::Snooker) {
    if (auto off = snookerBreakOff(context)) return *off;
  }
  const Vec2 apex = apexBall(context.view, context.balls);
  std::optional<PlannedShot> best;
  std::vector<PlannedShot> legal;
  for (const BreakStroke& candidate : measuredBreaks(context.view.rules.game)) {
    for (int side : {1, -1}) {
      PlannedShot shot = breakShot(context.view, apex, candidate, side);
      shot.choice = context.choice;
      if (!placementLegal(context, *shot.cue_ball_at)) continue;
      const auto trial = context.tryShot(shot);
      if (!trial) break;
      shot.value = breakValue(*trial);
      if (legalBreak(*trial)) {
        // Without sampling, the first measured break that works on this rack is played.
        if (context.samples == 0) return shot;
        legal.push_back(shot);
      }
      if (!best || shot.value > best->value) best = shot;
    }
  }
  if (!legal.empty()) return sampledBreak(context, legal);
  if (best) return *best;
  const auto spots = restingSpots(context);
  return fallbackShot(context, spots.empty() ? std::nullopt : std::optional<Vec2>(spots.front()));
}

}  // namespace pool::bot
