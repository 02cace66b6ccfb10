// The state of one rack between shots (8-, 9-, 10-ball; a game of three-cushion; a frame of
// snooker): whose turn, groups, phase, ball in hand, pending choice, fouls in a row, points, runs
// and breaks, the ball on.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "rules/ball_groups.h"

namespace pool::rules {

/// Where a rack stands. Break: the next shot is the opening break. Open: after the break, no
/// groups yet. Assigned: each player owns a group. Over: a winner is known.
enum class Phase : std::uint8_t { Break, Open, Assigned, Over };

/// Where the next shooter may place the cue ball before shooting. None: it is played where it
/// lies. Anywhere: anywhere on the slate. BehindHeadString: with its centre at x < head string x.
/// InTheD: snooker, with its centre in the D (on its lines or inside them).
enum class BallInHand : std::uint8_t { None, Anywhere, BehindHeadString, InTheD };

/// A choice the rules offer the next player before the next shot.
enum class Choice : std::uint8_t {
  PlayOn,       ///< accept the table as it lies and shoot (ball in hand as the state says)
  BallInHand,   ///< take the cue ball in hand behind the head string (object ball jumped on the
                ///< break)
  RespotEight,  ///< re-spot the 8 pocketed on the break and shoot
  ReBreak,      ///< re-rack; the player choosing breaks
  OpponentReBreaks,  ///< re-rack; the other player breaks (after an illegal break: its breaker
                     ///< again)
  PushOut,           ///< 9-/10-ball, the shot after the break: play a push-out (no contact
                     ///< fouls; the opponent then chooses who shoots next)
  PassBack,          ///< 9-/10-ball, after a push-out or a 10-ball shot that missed its call:
                     ///< the player who just shot must shoot again (snooker: after a foul)
  FreeBall,          ///< snooker, after a foul that leaves the cue ball snookered: play, any
                     ///< ball nominated (the intent's ball) taken as the ball on
  Replace,           ///< snooker, after a foul and a miss: the balls go back where they stood
                     ///< before it and the offender plays again
};

/// Why a game ended. Every reason but EightPocketed, RackBallPocketed and Forfeit is a loss of the
/// shooter.
enum class GameEnd : std::uint8_t {
  None,                     ///< the game goes on
  EightPocketed,            ///< the shooter legally pocketed the 8 in the called pocket: a win
  EightOnFoul,              ///< the 8 fell on a shot that fouled
  EightBeforeGroupCleared,  ///< the 8 fell while the shooter still had balls of the group (or no
                            ///< group)
  EightWithLastGroupBall,   ///< the 8 fell on the same shot as the last ball of the group
  EightWrongPocket,         ///< the 8 fell in a pocket other than the one called (or on a safety)
  EightOffTable,            ///< the 8 left the table after the break
  Forfeit,                  ///< a player gave up or was forfeited (outside the rules' judging)
  RackBallPocketed,  ///< 9-/10-ball: the shooter legally pocketed the 9 (the 10 called): a win
  ThreeFouls,        ///< 9-/10-ball: the shooter's third foul in a row: a loss
  PointsReached,     ///< three-cushion: the shooter scored the points that win the game
  FrameOver,         ///< snooker: the last ball is down (or the black scored on): the higher
                     ///< score wins
  ThreeMisses,       ///< snooker: the shooter's third miss in a row with a ball on in plain view
};

const char* toString(Phase phase);
const char* toString(BallInHand ball_in_hand);
const char* toString(Choice choice);
const char* toString(GameEnd end);

/// Seats are 0 and 1.
constexpr int kSeats = 2;

/// The other seat.
inline int opponentOf(int seat) {
  return 1 - seat;
}

/// A ball where it stood (table plane, m).
struct BallAt {
  int id = 0;
  double x = 0.0;
  double y = 0.0;
};

/// Everything the rules need to remember between shots of one rack.
struct GameState {
  Phase phase = Phase::Break;
  int shooter = 0;  ///< seat whose turn it is (the player holding `options`, if any)
  int breaker = 0;  ///< seat that broke this rack (a stalemate re-rack keeps it)
  std::array<Group, kSeats> groups{Group::None, Group::None};
  BallInHand ball_in_hand = BallInHand::BehindHeadString;  ///< for the shooter's next shot
  std::vector<Choice> options;  ///< non-empty: the shooter must choose one before shooting
  int dry_turns = 0;            ///< consecutive shots that pocketed no object ball
  int winner = -1;              ///< seat, once phase is Over
  GameEnd end = GameEnd::None;
  /// 9-/10-ball: each seat's fouls on its consecutive shots (a legal shot of that seat resets it).
  std::array<int, kSeats> fouls_in_row{0, 0};
  /// 9-/10-ball: the shot about to be played is a push-out (set by choosing Choice::PushOut).
  bool push_out = false;
  /// Three-cushion: each seat's points this game, its innings completed (a turn at the table
  /// ends one), its highest run, and the run of the player at the table.
  std::array<int, kSeats> points{0, 0};
  std::array<int, kSeats> innings{0, 0};
  std::array<int, kSeats> high_run{0, 0};
  int run = 0;
  /// Snooker: `points` is the frame score, `run` the current break, `high_run` each seat's
  /// highest break. The ball on (rules/snooker.h: kOnRed, kOnColour or a colour's id), whether
  /// the shooter plays a free ball, each seat's misses in a row with a ball on in plain view, and
  /// the layout (with its ball in hand, ball on and free ball) before the last foul and a miss, for
  /// Choice::Replace.
  int ball_on = 0;
  bool free_ball = false;
  std::array<int, kSeats> misses{0, 0};
  std::vector<BallAt> before_miss;
  BallInHand before_miss_in_hand = BallInHand::None;
  int before_miss_on = 0;
  bool before_miss_free_ball = false;
};

/// A fresh rack: the breaker to break with the cue ball in hand behind the head string.
GameState newRack(int breaker);

/// One-line summary for logs, e.g. "assigned, seat 1 to shoot (stripes), ball in hand anywhere".
std::string describe(const GameState& state);

}  // namespace pool::rules
