// Shots after the break: fouls, the 8, called balls, safeties and group assignment.
#include <algorithm>

#include "rules/eight_ball_steps.h"

namespace pool::rules::detail {
namespace {

bool contains(const std::vector<int>& ids, int id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// Where ball `id` lay before the shot, if it was on the table.
bool behindHeadString(int id, const std::vector<physics::Ball>& before, double head_string_x) {
  for (const auto& b : before) {
    if (b.id == id && physics::onTable(b.state)) return b.pos.x() < head_string_x;
  }
  return false;
}

// Fouls about the first contact: none, the wrong ball, a ball behind the head string played
// directly from the kitchen, and no cushion after contact when nothing fell.
void contactFouls(const GameState& state, const Shot& shot, const ShotFacts& facts,
                  const TableContext& table, std::vector<Foul>& fouls) {
  int first = facts.first_contact;
  if (first < 0) {
    fouls.push_back(Foul::NoBallHit);
    return;
  }
  if (!contains(legalFirstBalls(state, shot.before), first)) fouls.push_back(Foul::WrongBallFirst);
  if (state.ball_in_hand == BallInHand::BehindHeadString && !facts.cue_crossed_head_string &&
      behindHeadString(first, shot.before, table.spots.head_string_x)) {
    fouls.push_back(Foul::BehindHeadStringDirect);
  }
  if (!facts.cushion_after_contact && facts.objectBallsPocketed().empty()) {
    fouls.push_back(Foul::NoCushionAfterContact);
  }
}

std::vector<Foul> playFouls(const GameState& state, const Shot& shot, const ShotFacts& facts,
                            const TableContext& table) {
  std::vector<Foul> fouls;
  if (facts.isPocketed(physics::kCueBall)) fouls.push_back(Foul::CueBallPocketed);
  if (facts.isOffTable(physics::kCueBall)) fouls.push_back(Foul::CueBallOffTable);
  contactFouls(state, shot, facts, table, fouls);
  if (!facts.objectBallsOffTable().empty()) fouls.push_back(Foul::ObjectBallOffTable);
  if (shot.clock_expired) fouls.push_back(Foul::ShotClockExpired);
  return fouls;
}

// The last balls of the shooter's group all fell on this shot.
bool groupClearedNow(const GameState& state, const Shot& shot, const ShotFacts& facts) {
  if (state.phase != Phase::Assigned) return false;
  Group mine = state.groups[state.shooter];
  return std::all_of(shot.before.begin(), shot.before.end(), [&](const physics::Ball& b) {
    return !physics::onTable(b.state) || groupOf(b.id) != mine || facts.isPocketed(b.id);
  });
}

// What the 8 did to the game, if anything.
GameEnd eightOutcome(const GameState& state, const Shot& shot, const ShotFacts& facts,
                     bool fouled) {
  if (facts.isOffTable(kEightBall)) return GameEnd::EightOffTable;
  if (!facts.isPocketed(kEightBall)) return GameEnd::None;
  if (fouled) return GameEnd::EightOnFoul;
  if (!onTheEight(state, shot.before)) {
    return groupClearedNow(state, shot, facts) ? GameEnd::EightWithLastGroupBall
                                               : GameEnd::EightBeforeGroupCleared;
  }
  const Intent& intent = shot.intent;
  bool called =
      !intent.safety && intent.ball == kEightBall && intent.pocket == facts.pocketOf(kEightBall);
  return called ? GameEnd::EightPocketed : GameEnd::EightWrongPocket;
}

// Balls whose fall keeps the turn in casual play: the shooter's group, any but the 8 when open.
bool countsForShooter(const GameState& state, int id) {
  if (!isObjectBall(id) || id == kEightBall) return false;
  return state.phase == Phase::Open || groupOf(id) == state.groups[state.shooter];
}

// Casual play on an open table: the called ball's group, else the first ball hit if it fell, else
// the first ball of a group to fall.
Group casualGroup(const ShotFacts& facts, const std::vector<int>& scored) {
  if (contains(scored, facts.first_contact)) return groupOf(facts.first_contact);
  return groupOf(scored.front());
}

struct Score {
  bool keeps_turn = false;
  Group assigned = Group::None;
};

Score scoreShot(const GameState& state, const Shot& shot, const ShotFacts& facts, CallMode calls) {
  const Intent& intent = shot.intent;
  if (intent.safety) return {};
  bool open = state.phase == Phase::Open;
  if (intent.ball && facts.pocketOf(*intent.ball) == intent.pocket) {
    return {true, open ? groupOf(*intent.ball) : Group::None};
  }
  if (calls == CallMode::Standard) return {};
  std::vector<int> scored;
  for (int id : facts.objectBallsPocketed()) {
    if (countsForShooter(state, id)) scored.push_back(id);
  }
  if (scored.empty()) return {};
  return {true, open ? casualGroup(facts, scored) : Group::None};
}

}  // namespace

Judged judgePlay(const GameState& state, const Shot& shot, const ShotFacts& facts,
                 const TableContext& table, const EightBallConfig& config) {
  Judged judged;
  Verdict& v = judged.verdict;
  v.fouls = playFouls(state, shot, facts, table);
  v.pocketed = facts.objectBallsPocketed();
  v.off_table = facts.objectBallsOffTable();
  if (GameEnd end = eightOutcome(state, shot, facts, !v.fouls.empty()); end != GameEnd::None) {
    endGame(state, end, v);
    return judged;
  }
  if (!v.fouls.empty()) {
    passTurn(state, BallInHand::Anywhere, v);
    return judged;
  }
  Score score = scoreShot(state, shot, facts, config.calls);
  if (!score.keeps_turn) {
    passTurn(state, BallInHand::None, v);
    return judged;
  }
  v.turn_continues = true;
  v.next_shooter = state.shooter;
  v.assigned = score.assigned;
  return judged;
}

}  // namespace pool::rules::detail
