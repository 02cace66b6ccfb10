// The referee's verdict: names of fouls and a one-line summary.
#include "rules/verdict.h"

#include <algorithm>

namespace pool::rules {

const char* toString(Foul foul) {
  switch (foul) {
    case Foul::CueBallPocketed:
      return "cue_ball_pocketed";
    case Foul::CueBallOffTable:
      return "cue_ball_off_table";
    case Foul::NoBallHit:
      return "no_ball_hit";
    case Foul::WrongBallFirst:
      return "wrong_ball_first";
    case Foul::NoCushionAfterContact:
      return "no_cushion_after_contact";
    case Foul::ObjectBallOffTable:
      return "object_ball_off_table";
    case Foul::ShotClockExpired:
      return "shot_clock_expired";
    case Foul::IllegalBreak:
      return "illegal_break";
    case Foul::BehindHeadStringDirect:
      return "behind_head_string_direct";
    case Foul::BallNotOnPocketed:
      return "ball_not_on_pocketed";
    case Foul::PushStroke:
      return "push_stroke";
    case Foul::JumpShot:
      return "jump_shot";
    case Foul::FreeBallSnookers:
      return "free_ball_snookers";
  }
  return "unknown";
}

bool Verdict::hasFoul(Foul foul) const {
  return std::find(fouls.begin(), fouls.end(), foul) != fouls.end();
}

namespace {

std::string joinIds(const std::vector<int>& ids) {
  std::string text;
  for (int id : ids) {
    if (!text.empty()) text += ',';
    text += std::to_string(id);  // appended alone: g++ 12's -Wrestrict false positive at -O3
  }
  return text;
}

}  // namespace

std::string describe(const Verdict& verdict) {
  std::string text = verdict.legal() ? "legal" : "foul";
  for (Foul foul : verdict.fouls) text += std::string(" ") + toString(foul);
  if (verdict.penalty > 0) text += "; " + std::to_string(verdict.penalty) + " away";
  if (verdict.miss) text += "; a miss";
  if (verdict.scored > 0)
    text += verdict.scored == 1 ? "; a point" : "; " + std::to_string(verdict.scored) + " points";
  if (!verdict.pocketed.empty()) text += "; pocketed " + joinIds(verdict.pocketed);
  if (!verdict.off_table.empty()) text += "; off table " + joinIds(verdict.off_table);
  if (verdict.assigned != Group::None)
    text += std::string("; shooter takes ") + toString(verdict.assigned);
  if (verdict.game_over) {
    return text + "; game over, seat " + std::to_string(verdict.winner) + " wins (" +
           toString(verdict.end) + ")";
  }
  if (verdict.rerack) text += verdict.stalemate ? "; stalemate, re-rack" : "; re-rack";
  return text + "; " + describe(verdict.next);
}

}  // namespace pool::rules
