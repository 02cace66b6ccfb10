// Three-cushion's rules: the point from the cue ball's contacts and cushions, innings, runs, the
// re-spot of a ball that left the table.
#include "rules/three_cushion.h"

#include <algorithm>
#include <array>

#include "rules/log_check.h"
#include "rules/verdict_steps.h"

namespace pool::rules {
namespace {

using physics::EventType;

/// Where a ball that left the table goes back (UMB: the red on the top spot, the striker's ball on
/// the bottom spot, the opponent's on the centre spot; a spot taken sends it to the spot of the
/// ball on its own, else to the free one).
Eigen::Vector2d caromSpot(int id, int shooter_ball, const std::vector<physics::Ball>& after,
                          const std::vector<Respot>& placed, const TableContext& table) {
  const table::Spots& s = table.spots;
  const auto own = [&](int ball) {
    if (ball == kCaromRed) return s.foot_spot;
    return ball == shooter_ball ? s.head_spot : s.centre_spot;
  };
  const std::array<Eigen::Vector2d, 3> all{s.foot_spot, s.head_spot, s.centre_spot};
  const auto taken = [&](const Eigen::Vector2d& spot) {
    const double clear = 2.0 * table.ball_radius;
    for (const auto& b : after) {
      if (b.id == id || !onTable(b.state)) continue;
      if ((b.pos.head<2>() - spot).norm() < clear) return true;
    }
    for (const Respot& r : placed) {
      if ((r.pos - spot).norm() < clear) return true;
    }
    return false;
  };
  const Eigen::Vector2d mine = own(id);
  if (!taken(mine)) return mine;
  for (const auto& b : after) {  // the spot of the ball that is on mine
    if (b.id == id || !onTable(b.state)) continue;
    if ((b.pos.head<2>() - mine).norm() < 2.0 * table.ball_radius && !taken(own(b.id)))
      return own(b.id);
  }
  for (const auto& spot : all) {
    if (!taken(spot)) return spot;
  }
  return mine;
}

}  // namespace

int caromBallOf(const GameState& state, int seat) {
  return seat == state.breaker ? kCaromWhite : kCaromYellow;
}

Result<CaromFacts> caromFacts(const Shot& shot, int cue) {
  if (auto ok = checkShot(shot, cue); !ok) return Result<CaromFacts>::fail(ok.error());
  CaromFacts f;
  int cushions = 0;
  for (const auto& e : shot.events) {
    if (e.type == EventType::OffTable) f.off_table.push_back(e.ball_a);
    if (e.type == EventType::BallCushion && e.ball_a == cue) ++cushions;
    if (e.type != EventType::BallBall || (e.ball_a != cue && e.ball_b != cue)) continue;
    const int other = e.ball_a == cue ? e.ball_b : e.ball_a;
    if (f.first < 0) {
      f.first = other;
    } else if (other != f.first && f.second < 0) {
      f.second = other;
      f.cushions = cushions;
    }
  }
  if (f.second < 0) f.cushions = cushions;
  return Result<CaromFacts>::ok(f);
}

Check<> checkCaromIntent(const Intent& intent) {
  if (intent.ball || !intent.pocket.empty())
    return Check<>::refuse("no_call", "three-cushion has no called ball or pocket");
  if (intent.safety) return Check<>::refuse("no_safety", "three-cushion has no declared safety");
  if (intent.choice) return Check<>::refuse("no_choice", "three-cushion offers no choice");
  return Check<>::pass();
}

Result<Verdict> judgeThreeCushion(const GameState& state, const Shot& shot,
                                  const TableContext& table, const ThreeCushionConfig& config) {
  if (state.phase == Phase::Over) return Result<Verdict>::fail("the game is over");
  if (auto ok = checkCaromIntent(shot.intent); !ok) return Result<Verdict>::fail(ok.error());
  const int shooter = state.shooter;
  const int cue = caromBallOf(state, shooter);
  Verdict v;
  CaromFacts facts;
  if (shot.clock_expired && shot.events.empty()) {
    v.fouls.push_back(Foul::ShotClockExpired);
  } else {
    auto distilled = caromFacts(shot, cue);
    if (!distilled) return Result<Verdict>::fail(distilled.error());
    facts = *distilled;
    if (shot.clock_expired) v.fouls.push_back(Foul::ShotClockExpired);
    // The opening: the breaker's ball must hit the red first.
    if (state.phase == Phase::Break && facts.first >= 0 && facts.first != kCaromRed)
      v.fouls.push_back(Foul::WrongBallFirst);
    for (int id : facts.off_table) {
      const Foul foul = id == cue ? Foul::CueBallOffTable : Foul::ObjectBallOffTable;
      if (!v.hasFoul(foul)) v.fouls.push_back(foul);
      v.off_table.push_back(id);
    }
  }
  for (int id : v.off_table) {
    if (detail::ballOnTable(id, shot.before) && !detail::ballOnTable(id, shot.after))
      v.respots.push_back({id, caromSpot(id, cue, shot.after, v.respots, table)});
  }

  GameState next = state;
  next.phase = Phase::Open;
  next.ball_in_hand = BallInHand::None;
  next.options.clear();
  const bool scored = v.legal() && facts.point();
  if (scored) {
    v.scored = 1;
    ++next.points[shooter];
    ++next.run;
    next.high_run[shooter] = std::max(next.high_run[shooter], next.run);
    v.turn_continues = true;
    v.next_shooter = shooter;
    if (next.points[shooter] >= config.points_to) {
      ++next.innings[shooter];  // the winning inning ends with the game
      v.game_over = true;
      v.winner = shooter;
      v.end = GameEnd::PointsReached;
      v.turn_continues = false;
      next.phase = Phase::Over;
      next.winner = shooter;
      next.end = GameEnd::PointsReached;
    }
  } else {
    ++next.innings[shooter];
    next.run = 0;
    v.next_shooter = opponentOf(shooter);
  }
  next.shooter = v.next_shooter;
  v.ball_in_hand = BallInHand::None;
  v.next = next;
  return Result<Verdict>::ok(v);
}

}  // namespace pool::rules
