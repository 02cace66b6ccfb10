// What the referee says about one shot (or one choice): fouls, balls down, who shoots next, the new
// state.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "rules/ball_groups.h"
#include "rules/game_state.h"

namespace pool::rules {

/// A foul. Every foul but IllegalBreak gives the opponent the cue ball in hand (anywhere after the
/// break; behind the head string when it happens on the break).
enum class Foul : std::uint8_t {
  CueBallPocketed,  ///< scratch
  CueBallOffTable,
  NoBallHit,              ///< the cue ball touched no object ball
  WrongBallFirst,         ///< the first ball touched was not one the shooter may hit first
  NoCushionAfterContact,  ///< after the first contact no ball reached a cushion and none fell
  ObjectBallOffTable,
  ShotClockExpired,
  IllegalBreak,            ///< no ball pocketed and fewer than four object balls reached a cushion
  BehindHeadStringDirect,  ///< in hand behind the head string, hit a ball behind it without
                           ///< crossing first
  BallNotOnPocketed,       ///< snooker: a ball that was not on fell
  PushStroke,              ///< snooker: a ball touching the cue ball moved with the stroke
  JumpShot,                ///< snooker: the cue ball jumped over an object ball
  FreeBallSnookers,        ///< snooker: the free ball snookers the next player on the ball on
};

const char* toString(Foul foul);

/// A ball to put back on the table (table plane, m).
struct Respot {
  int id = 0;
  Eigen::Vector2d pos = Eigen::Vector2d::Zero();
};

/// The referee's verdict.
struct Verdict {
  std::vector<Foul> fouls;    ///< empty: no foul
  std::vector<int> pocketed;  ///< object balls pocketed on the shot, in time order (they stay down)
  std::vector<int> off_table;    ///< object balls that left the table (they stay off, except the 8)
  bool turn_continues = false;   ///< the shooter shoots again
  Group assigned = Group::None;  ///< the group this shot gave the shooter (None: no change)
  int next_shooter = 0;          ///< seat
  BallInHand ball_in_hand = BallInHand::None;  ///< for the next shooter
  std::vector<Respot> respots;                 ///< balls to put back now, at these positions
  std::vector<Choice> options;                 ///< the next shooter must choose one of these first
  bool rerack = false;     ///< rack again; next.breaker breaks (a choice or a stalemate)
  bool stalemate = false;  ///< the re-rack is because of a stalemate
  int scored = 0;          ///< points the shot scored (three-cushion: 1 for a point)
  int penalty = 0;         ///< snooker: the points a foul gave the opponent
  bool miss = false;       ///< snooker: the foul was called a foul and a miss
  bool game_over = false;
  int winner = -1;              ///< seat, when game_over
  GameEnd end = GameEnd::None;  ///< why the game ended
  GameState next;               ///< the state for the next shot

  bool legal() const { return fouls.empty(); }
  bool hasFoul(Foul foul) const;
};

/// One-line summary, e.g. "foul cue_ball_pocketed; pocketed 3; seat 1 next, ball in hand anywhere".
std::string describe(const Verdict& verdict);

}  // namespace pool::rules
