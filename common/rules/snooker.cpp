// Snooker's rules: the ball on, scores and penalties, free balls, misses, re-spotted colours and
// the end of a frame (WPBSA, Official Rules of Snooker).
#include "rules/snooker.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "rules/jump_shot.h"
#include "rules/shot_facts.h"
#include "rules/verdict_steps.h"
#include "table/rack.h"
#include "table/segment_distance.h"

namespace pool::rules {
namespace {

using physics::EventType;
using Vec2 = Eigen::Vector2d;
using table::segmentDistance;

/// A ball counts as touching the cue ball when their surfaces are this close, m (Section 3,
/// "Touching Ball": the referee's "touching ball"; a tenth of a millimetre is below what an eye can
/// tell apart).
constexpr double kTouching = 1e-4;
/// The re-spot search walks its line in steps of this length, m.
constexpr double kRespotStep = 5e-4;
/// The least penalty (Section 3, "Fouls").
constexpr int kMinPenalty = 4;
/// A foul after a red before a colour is nominated or hit (Section 3, "Fouls").
constexpr int kUnnominatedPenalty = 7;

bool hasId(const std::vector<int>& ids, int id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

const physics::Ball* ballById(const std::vector<physics::Ball>& balls, int id) {
  for (const auto& b : balls) {
    if (b.id == id) return &b;
  }
  return nullptr;
}

std::vector<int> objectIdsOn(const std::vector<physics::Ball>& balls) {
  std::vector<int> ids;
  for (const auto& b : balls) {
    if (b.id != physics::kCueBall && physics::onTable(b.state)) ids.push_back(b.id);
  }
  std::sort(ids.begin(), ids.end());
  return ids;
}

int redsLeft(const std::vector<physics::Ball>& balls) {
  int n = 0;
  for (int id : objectIdsOn(balls)) n += isRed(id) ? 1 : 0;
  return n;
}

/// The lowest colour on the table; 0 when none is.
int lowestColourOn(const std::vector<physics::Ball>& balls) {
  for (int id : objectIdsOn(balls)) {
    if (isColour(id)) return id;
  }
  return 0;
}

/// Whether the cue ball travelling straight from `from` to `to` (its centre's path) passes clear
/// of every ball on the table but `target` and the balls of `ignore` (balls on never snooker).
bool straightPathClear(const std::vector<physics::Ball>& balls, const Vec2& from, const Vec2& to,
                       int target, const std::vector<int>& ignore, double r) {
  for (const auto& b : balls) {
    if (b.id == physics::kCueBall || b.id == target || !physics::onTable(b.state)) continue;
    if (hasId(ignore, b.id)) continue;
    if (segmentDistance(b.pos.head<2>(), from, to) < 2.0 * r - 1e-9) return false;
  }
  return true;
}

/// Where the cue ball's centre is when it strikes `target` at `offset` (−1 and 1: its extreme
/// edges, 0: full) from `from`.
Vec2 strikePoint(const Vec2& from, const Vec2& target, double offset, double r) {
  const Vec2 d = target - from;
  const double len = d.norm();
  if (len <= 0.0) return target;
  const Vec2 n(-d.y() / len, d.x() / len);
  return target + offset * 2.0 * r * n;
}

/// Counts the parts of `target` (at `offsets`) a straight stroke from the cue ball reaches.
int partsReachable(const std::vector<physics::Ball>& balls, const Vec2& cue, int target,
                   const std::vector<int>& on, const std::vector<double>& offsets, double r) {
  const physics::Ball* t = ballById(balls, target);
  if (!t || !physics::onTable(t->state)) return 0;
  int n = 0;
  for (double k : offsets) {
    if (straightPathClear(balls, cue, strikePoint(cue, t->pos.head<2>(), k, r), target, on, r)) ++n;
  }
  return n;
}

std::optional<Vec2> cueBallAt(const std::vector<physics::Ball>& balls) {
  const physics::Ball* cue = ballById(balls, physics::kCueBall);
  if (!cue || !physics::onTable(cue->state)) return std::nullopt;
  return cue->pos.head<2>();
}

/// Section 3, "Spotting Colours": a colour's own spot; else the highest-valued free spot; else the
/// nearest free point from its own spot toward the top cushion; else toward baulk.
Vec2 respotColour(int colour, const std::vector<Vec2>& taken, const TableContext& table) {
  const double r = table.ball_radius;
  const Vec2 own = *table::snookerSpotOf(table.spec, colour);
  if (table::isFree(own, r, taken)) return own;
  for (int c = table::kSnookerBlack; c >= table::kSnookerYellow; --c) {
    const Vec2 spot = *table::snookerSpotOf(table.spec, c);
    if (table::isFree(spot, r, taken)) return spot;
  }
  const double top = table.spec.length / 2.0 - r;
  for (double x = own.x(); x <= top; x += kRespotStep) {
    if (table::isFree({x, own.y()}, r, taken)) return {x, own.y()};
  }
  for (double x = own.x(); x >= -top; x -= kRespotStep) {
    if (table::isFree({x, own.y()}, r, taken)) return {x, own.y()};
  }
  return own;  // the whole line is taken: nothing better exists
}

/// The balls on table `balls` once `respots` are in place.
std::vector<physics::Ball> respotted(std::vector<physics::Ball> balls,
                                     const std::vector<Respot>& respots, double r) {
  for (const Respot& s : respots) {
    for (auto& b : balls) {
      if (b.id != s.id) continue;
      b = physics::restingBall(s.id, s.pos, r);
    }
  }
  return balls;
}

/// What the stroke was played at: the balls the cue ball may hit first, the nominated colour,
/// the free ball, and the value a foul is measured from.
struct StrokeTarget {
  std::vector<int> first;  ///< balls the cue ball may hit first
  int nominated = -1;      ///< kOnColour: the colour nominated or hit first; -1: none
  int free_ball = -1;      ///< the ball nominated (or hit first) as a free ball; -1: none
  int on_value = 0;        ///< the value of the ball on (7 for a colour never nominated)
};

StrokeTarget strokeTarget(const GameState& state, const Shot& shot, int first_contact) {
  StrokeTarget t;
  const std::vector<int> on = snookerBallsOn(state, shot.before);
  t.first = on;
  const int nominated = shot.intent.ball.value_or(-1);
  if (state.ball_on == kOnColour) {
    t.nominated = nominated >= 0 ? nominated : (isColour(first_contact) ? first_contact : -1);
    if (nominated >= 0) t.first = {nominated};
    t.on_value = t.nominated >= 0 ? snookerValue(t.nominated) : kUnnominatedPenalty;
  } else {
    t.on_value = state.ball_on == kOnRed ? 1 : snookerValue(state.ball_on);
  }
  if (state.free_ball) {
    const int free = nominated >= 0 ? nominated : first_contact;
    if (free > 0 && !hasId(on, free)) {
      t.free_ball = free;
      t.first.push_back(free);
    }
  }
  return t;
}

/// The balls touching the cue ball before the stroke.
std::vector<int> touchingCueBall(const std::vector<physics::Ball>& before, double r) {
  std::vector<int> ids;
  const auto cue = cueBallAt(before);
  if (!cue) return ids;
  for (const auto& b : before) {
    if (b.id == physics::kCueBall || !physics::onTable(b.state)) continue;
    if ((b.pos.head<2>() - *cue).norm() <= 2.0 * r + kTouching) ids.push_back(b.id);
  }
  return ids;
}

/// Section 3, "Touching Ball": a touching ball the stroke moved (the cue ball meets it at once).
bool touchingBallPushed(const Shot& shot, const std::vector<int>& touching) {
  constexpr double kAtOnce = 0.01;  // s: a contact this soon after the strike is the stroke's own
  for (const auto& e : shot.events) {
    if (e.type != EventType::BallBall || e.t > kAtOnce) continue;
    const int other = e.ball_a == physics::kCueBall   ? e.ball_b
                      : e.ball_b == physics::kCueBall ? e.ball_a
                                                      : -1;
    if (hasId(touching, other)) return true;
  }
  return false;
}

/// Whether the free ball, left on the table, snookers the cue ball on `on` (0 all the reds, else
/// that colour): snookered with it and not without it. Never with only the pink and
/// the black left before the stroke.
bool freeBallSnookers(const Shot& shot, int free_ball, int on_now, double r) {
  const physics::Ball* ball = ballById(shot.after, free_ball);
  if (!ball || !physics::onTable(ball->state)) return false;
  std::vector<int> left = objectIdsOn(shot.before);
  std::sort(left.begin(), left.end());
  if (left == std::vector<int>{table::kSnookerPink, table::kSnookerBlack}) return false;
  GameState following;
  following.ball_on = on_now;
  const std::vector<int> on = snookerBallsOn(following, shot.after);
  std::vector<physics::Ball> without = shot.after;
  std::erase_if(without, [&](const physics::Ball& b) { return b.id == free_ball; });
  return isSnookered(shot.after, on, r) && !isSnookered(without, on, r);
}

std::vector<BallAt> standingLayout(const std::vector<physics::Ball>& balls) {
  std::vector<BallAt> out;
  for (const auto& b : balls) {
    if (physics::onTable(b.state)) out.push_back({b.id, b.pos.x(), b.pos.y()});
  }
  return out;
}

/// Nothing left to put back: the position before a miss is forgotten.
void forgetMiss(GameState& state) {
  state.before_miss.clear();
  state.before_miss_in_hand = BallInHand::None;
  state.before_miss_on = kOnRed;
  state.before_miss_free_ball = false;
}

void endTheFrame(GameState& next, Verdict& v, int winner, GameEnd end) {
  v.game_over = true;
  v.winner = winner;
  v.end = end;
  v.turn_continues = false;
  v.next_shooter = winner;
  v.ball_in_hand = BallInHand::None;
  v.options.clear();
  next.phase = Phase::Over;
  next.winner = winner;
  next.end = end;
  next.shooter = winner;
  next.ball_in_hand = BallInHand::None;
  next.options.clear();
}

}  // namespace

int snookerValue(int id) {
  if (isRed(id)) return 1;
  if (isColour(id)) return id - table::kSnookerYellow + 2;
  return 0;
}

bool isRed(int id) {
  return id >= 1 && id <= table::kSnookerReds;
}

bool isColour(int id) {
  return id >= table::kSnookerYellow && id <= table::kSnookerBlack;
}

std::vector<int> snookerBallsOn(const GameState& state, const std::vector<physics::Ball>& balls) {
  std::vector<int> on;
  for (int id : objectIdsOn(balls)) {
    const bool is_on = state.ball_on == kOnRed      ? isRed(id)
                       : state.ball_on == kOnColour ? isColour(id)
                                                    : id == state.ball_on;
    if (is_on) on.push_back(id);
  }
  return on;
}

int pointsRemaining(const GameState& state, const std::vector<physics::Ball>& balls) {
  // While reds remain every colour goes back on its spot: all six are still to come.
  int points = 8 * redsLeft(balls) + (state.ball_on == kOnColour ? 7 : 0);
  for (int id : objectIdsOn(balls)) points += isColour(id) ? snookerValue(id) : 0;
  return points;
}

int snookersRequired(const GameState& state, const std::vector<physics::Ball>& balls, int seat) {
  const int behind = state.points[static_cast<std::size_t>(opponentOf(seat))] -
                     state.points[static_cast<std::size_t>(seat)];
  return std::max(0, behind - pointsRemaining(state, balls));
}

bool isSnookered(const std::vector<physics::Ball>& balls, const std::vector<int>& on,
                 double ball_radius) {
  const auto cue = cueBallAt(balls);
  if (!cue || on.empty()) return false;
  for (int id : on) {
    if (partsReachable(balls, *cue, id, on, {-1.0, 1.0}, ball_radius) == 2) return false;
  }
  return true;
}

bool inPlainView(const std::vector<physics::Ball>& balls, const std::vector<int>& on,
                 double ball_radius) {
  const auto cue = cueBallAt(balls);
  if (!cue) return false;
  const std::vector<double> offsets{-1.0, -0.75, -0.5, -0.25, 0.0, 0.25, 0.5, 0.75, 1.0};
  return std::any_of(on.begin(), on.end(), [&](int id) {
    return partsReachable(balls, *cue, id, on, offsets, ball_radius) > 0;
  });
}

Check<> checkSnookerIntent(const GameState& state, const Intent& intent) {
  if (!intent.pocket.empty()) return Check<>::refuse("no_call", "snooker calls no pocket");
  if (intent.safety) return Check<>::refuse("no_safety", "snooker has no declared safety");
  if (intent.choice) {
    return Check<>::refuse("choice_needs_no_shot",
                           "snooker's choices are made before the stroke, not with it");
  }
  if (!intent.ball) return Check<>::pass();
  const int id = *intent.ball;
  if (state.free_ball) {
    if (id < 1 || id > table::kSnookerBlack)
      return Check<>::refuse("not_object_ball", "a free ball must be a red or a colour");
    return Check<>::pass();
  }
  if (state.ball_on != kOnColour) {
    return Check<>::refuse("nothing_to_nominate",
                           "a ball is nominated only when on a colour or playing a free ball");
  }
  if (!isColour(id)) return Check<>::refuse("not_a_colour", "the nominated ball must be a colour");
  return Check<>::pass();
}

GameState newFrame(int breaker) {
  GameState state = newRack(breaker);
  state.ball_in_hand = BallInHand::InTheD;
  state.ball_on = kOnRed;
  return state;
}

Result<Verdict> judgeSnooker(const GameState& state, const Shot& shot, const TableContext& table,
                             const SnookerConfig& config) {
  if (state.phase == Phase::Over) return Result<Verdict>::fail("the frame is over");
  if (!state.options.empty()) return Result<Verdict>::fail("a choice is pending");
  if (auto ok = checkSnookerIntent(state, shot.intent); !ok)
    return Result<Verdict>::fail(ok.error());
  const double r = table.ball_radius;
  const int shooter = state.shooter;
  const int opponent = opponentOf(shooter);
  Verdict v;
  ShotFacts facts;
  const bool no_stroke = shot.clock_expired && shot.events.empty();
  if (!no_stroke) {
    if (auto ok = detail::checkCueInHand(state, shot, table); !ok)
      return Result<Verdict>::fail(ok.error());
    auto distilled = distilShot(shot, table.spots.head_string_x);
    if (!distilled) return Result<Verdict>::fail(distilled.error());
    facts = *distilled;
  }
  const StrokeTarget target = strokeTarget(state, shot, facts.first_contact);
  const std::vector<int> touching = touchingCueBall(shot.before, r);
  const bool touching_on = std::any_of(touching.begin(), touching.end(),
                                       [&](int id) { return hasId(target.first, id); });

  // Fouls, and the values they are measured from (Section 3, "Fouls").
  int penalty = target.on_value;
  const auto involve = [&](int id) { penalty = std::max(penalty, snookerValue(id)); };
  bool failed_to_hit = false;
  if (shot.clock_expired) v.fouls.push_back(Foul::ShotClockExpired);
  if (!no_stroke) {
    if (facts.isPocketed(physics::kCueBall)) v.fouls.push_back(Foul::CueBallPocketed);
    if (facts.isOffTable(physics::kCueBall)) v.fouls.push_back(Foul::CueBallOffTable);
    if (facts.first_contact < 0 && !touching_on) {
      v.fouls.push_back(Foul::NoBallHit);
      failed_to_hit = true;
    } else if (facts.first_contact >= 0 && !hasId(target.first, facts.first_contact)) {
      v.fouls.push_back(Foul::WrongBallFirst);
      involve(facts.first_contact);
      failed_to_hit = true;
    }
    if (touchingBallPushed(shot, touching)) v.fouls.push_back(Foul::PushStroke);
    // Section 2, "Definitions" ("Jump Shot"), and Section 3, "Fouls".
    if (jumpedOverABall(shot, r)) v.fouls.push_back(Foul::JumpShot);
  }
  // Which pots are the stroke's own: reds when on a red (a free ball with them), the nominated
  // colour, the one colour on, or the free ball.
  const auto legalPot = [&](int id) {
    if (id == target.free_ball) return true;
    if (state.ball_on == kOnRed) return isRed(id);
    if (state.ball_on == kOnColour) return id == target.nominated;
    return id == state.ball_on;
  };
  const std::vector<int> potted = facts.objectBallsPocketed();
  for (int id : potted) {
    v.pocketed.push_back(id);
    if (!legalPot(id)) {
      if (!v.hasFoul(Foul::BallNotOnPocketed)) v.fouls.push_back(Foul::BallNotOnPocketed);
      involve(id);
    }
  }
  if (state.ball_on == kOnColour && std::count_if(potted.begin(), potted.end(), isColour) > 1 &&
      !v.hasFoul(Foul::BallNotOnPocketed)) {
    v.fouls.push_back(Foul::BallNotOnPocketed);
  }
  for (int id : facts.objectBallsOffTable()) {
    v.off_table.push_back(id);
    if (!v.hasFoul(Foul::ObjectBallOffTable)) v.fouls.push_back(Foul::ObjectBallOffTable);
    involve(id);
  }
  // Section 3, "Snookered after a Foul": the free ball may not snooker the next player on all
  // the reds or the ball on, unless only the pink and the black remain.
  // The reds or the ball on are the free-ball stroke's own.
  if (!no_stroke && target.free_ball >= 0 &&
      freeBallSnookers(shot, target.free_ball, state.ball_on, r)) {
    v.fouls.push_back(Foul::FreeBallSnookers);
  }
  penalty = std::max(penalty, kMinPenalty);

  // Balls back on the table: colours potted while reds were on the table before the stroke, or
  // after the last red, or on a foul, or as a free ball; colours off the table; colours the
  // watchdog took off. The highest first (Section 3, "Spotting Colours").
  const bool reds_before = redsLeft(shot.before) > 0;
  std::vector<int> back;
  for (int id : potted) {
    if (!isColour(id)) continue;
    if (reds_before || state.ball_on == kOnColour || !v.legal() || id == target.free_ball)
      back.push_back(id);
  }
  for (int id : facts.objectBallsOffTable()) {
    if (isColour(id)) back.push_back(id);
  }
  for (int id : facts.removed) {
    if (isColour(id)) back.push_back(id);
  }
  std::sort(back.begin(), back.end(), std::greater<>());
  back.erase(std::unique(back.begin(), back.end()), back.end());
  std::vector<Vec2> taken;
  for (const auto& b : shot.after) {
    if (physics::onTable(b.state) && !hasId(back, b.id)) taken.push_back(b.pos.head<2>());
  }
  // Every colour whose own spot is free goes there first; then the others, the highest first,
  // onto what is left.
  std::vector<int> elsewhere;
  for (int id : back) {
    const Vec2 own = *table::snookerSpotOf(table.spec, id);
    if (!table::isFree(own, r, taken)) {
      elsewhere.push_back(id);
      continue;
    }
    v.respots.push_back({id, own});
    taken.push_back(own);
  }
  for (int id : elsewhere) {
    const Vec2 at = respotColour(id, taken, table);
    v.respots.push_back({id, at});
    taken.push_back(at);
  }
  std::vector<physics::Ball> after = respotted(shot.after, v.respots, r);

  GameState next = state;
  next.phase = Phase::Open;
  next.options.clear();
  next.free_ball = false;
  forgetMiss(next);
  // A clock run out before the stroke leaves a cue ball in hand in hand.
  const bool cue_lost = no_stroke ? state.ball_in_hand != BallInHand::None
                                  : facts.cueBallLost() || facts.isRemoved(0);
  v.ball_in_hand = cue_lost ? BallInHand::InTheD : BallInHand::None;
  const std::vector<int> before_on = objectIdsOn(shot.before);
  const bool black_alone = before_on.size() == 1 && before_on[0] == table::kSnookerBlack;
  int scored = 0;
  if (v.legal()) {
    for (int id : potted) {
      // A free ball scores as the ball on; with the ball on potted too, only the ball on counts
      // unless the ball on is a red (Section 3, "Snookered after a Foul").
      if (id == target.free_ball) {
        const bool with_on = std::any_of(potted.begin(), potted.end(), [&](int p) {
          return p != target.free_ball && legalPot(p);
        });
        if (state.ball_on == kOnRed || !with_on) scored += target.on_value;
      } else {
        scored += snookerValue(id);
      }
    }
    next.misses[static_cast<std::size_t>(shooter)] = 0;
  } else {
    v.penalty = penalty;
    next.points[static_cast<std::size_t>(opponent)] += penalty;
    // Section 3, "Foul and a Miss": a foul that does not first hit a ball on is a miss, unless only
    // the black is left or either player needed snookers before or after the stroke.
    GameState scored_after = next;
    scored_after.ball_on = redsLeft(after) > 0 ? kOnRed : lowestColourOn(after);
    const bool snookers_needed = snookersRequired(state, shot.before, 0) > 0 ||
                                 snookersRequired(state, shot.before, 1) > 0 ||
                                 snookersRequired(scored_after, after, 0) > 0 ||
                                 snookersRequired(scored_after, after, 1) > 0;
    v.miss = failed_to_hit && !black_alone && !snookers_needed;
    const bool plain = inPlainView(shot.before, snookerBallsOn(state, shot.before), r);
    int& misses = next.misses[static_cast<std::size_t>(shooter)];
    misses = v.miss && plain ? misses + 1 : 0;
    if (v.miss) {
      next.before_miss = standingLayout(shot.before);
      next.before_miss_in_hand = state.ball_in_hand;
      next.before_miss_on = state.ball_on;
      next.before_miss_free_ball = state.free_ball;
    }
  }
  v.scored = scored;
  if (scored > 0) {
    next.points[static_cast<std::size_t>(shooter)] += scored;
    next.run += scored;
    next.high_run[static_cast<std::size_t>(shooter)] =
        std::max(next.high_run[static_cast<std::size_t>(shooter)], next.run);
    v.turn_continues = true;
    v.next_shooter = shooter;
  } else {
    next.run = 0;
    v.next_shooter = opponent;
  }
  v.turn_continues = scored > 0;

  // The ball on next (Section 3, "Play").
  const int reds_after = redsLeft(after);
  if (v.turn_continues && state.ball_on == kOnRed) {
    next.ball_on = kOnColour;
  } else {
    next.ball_on = reds_after > 0 ? kOnRed : lowestColourOn(after);
  }
  next.shooter = v.next_shooter;
  next.ball_in_hand = v.ball_in_hand;
  next.dry_turns = potted.empty() ? state.dry_turns + 1 : 0;

  // The end of the frame (Section 3, "Play").
  bool respotted_black = false;
  const int p0 = next.points[0], p1 = next.points[1];
  if (next.misses[static_cast<std::size_t>(shooter)] >= 3) {
    endTheFrame(next, v, opponent, GameEnd::ThreeMisses);
  } else if (objectIdsOn(after).empty() || (black_alone && (scored > 0 || !v.legal()))) {
    if (p0 != p1) {
      endTheFrame(next, v, p0 > p1 ? 0 : 1, GameEnd::FrameOver);
    } else {
      // A tie: the black goes back on its spot (potted or not) and the non-breaker plays at it
      // from the D, the cue ball in hand; nothing is left to choose.
      std::erase_if(v.respots, [](const Respot& s) { return s.id == table::kSnookerBlack; });
      v.respots.push_back({table::kSnookerBlack, respotColour(table::kSnookerBlack, {}, table)});
      respotted_black = true;
      v.turn_continues = false;
      v.next_shooter = opponentOf(state.breaker);
      v.ball_in_hand = BallInHand::InTheD;
      next.shooter = v.next_shooter;
      next.ball_in_hand = BallInHand::InTheD;
      next.ball_on = table::kSnookerBlack;
      next.run = 0;
    }
  }
  if (!v.game_over && !respotted_black && !v.legal() && v.next_shooter == opponent) {
    // The incoming player answers the foul first.
    v.options = {Choice::PlayOn};
    if (!cue_lost && isSnookered(after, snookerBallsOn(next, after), r))
      v.options.push_back(Choice::FreeBall);
    v.options.push_back(Choice::PassBack);
    if (v.miss) v.options.push_back(Choice::Replace);
    next.options = v.options;
  }
  v.next = next;
  if (v.legal()) detail::checkStalemate(state, next.dry_turns, config.stalemate_turns, v);
  if (v.rerack) {
    v.next = newFrame(state.breaker);
    v.next_shooter = state.breaker;
    v.ball_in_hand = BallInHand::InTheD;
  }
  return Result<Verdict>::ok(v);
}

Result<Verdict> applySnookerChoice(const GameState& state, Choice choice) {
  if (std::find(state.options.begin(), state.options.end(), choice) == state.options.end()) {
    return Result<Verdict>::fail(std::string("choice ") + toString(choice) + " is not offered");
  }
  const int offender = opponentOf(state.shooter);
  Verdict v;
  GameState next = state;
  next.options.clear();
  next.free_ball = false;
  switch (choice) {
    case Choice::PlayOn:
    case Choice::FreeBall:
      next.free_ball = choice == Choice::FreeBall;
      next.misses[static_cast<std::size_t>(offender)] = 0;
      forgetMiss(next);
      break;
    case Choice::PassBack:
      next.shooter = offender;
      forgetMiss(next);
      break;
    case Choice::Replace:
      if (state.before_miss.empty())
        return Result<Verdict>::fail("there is no position before a miss to put back");
      for (const BallAt& b : state.before_miss) v.respots.push_back({b.id, Vec2(b.x, b.y)});
      next.shooter = offender;
      next.ball_in_hand = state.before_miss_in_hand;
      next.ball_on = state.before_miss_on;
      next.free_ball = state.before_miss_free_ball;
      forgetMiss(next);
      break;
    default:
      return Result<Verdict>::fail(std::string("choice ") + toString(choice) +
                                   " is not part of snooker");
  }
  v.turn_continues = next.shooter == state.shooter;
  v.next_shooter = next.shooter;
  v.ball_in_hand = next.ball_in_hand;
  v.next = next;
  return Result<Verdict>::ok(v);
}

}  // namespace pool::rules
