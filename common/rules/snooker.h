// Snooker's rules (WPBSA, Official Rules of Snooker, Section 3): the ball on, scoring, fouls and
// their values, free balls, the miss, re-spotting, the end of a frame.
#pragma once

#include <vector>

#include "core/check.h"
#include "core/result.h"
#include "physics/ball.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/table_context.h"
#include "rules/verdict.h"

namespace pool::rules {

/// GameState::ball_on in snooker: any red, or a colour of the shooter's choice (after a red,
/// nominated by the intent's ball or, unnominated, the colour the cue ball first hits: Section 3,
/// "Play"); otherwise the id of the one colour on (16–21: the colours in their order, once the reds
/// are gone).
inline constexpr int kOnRed = 0;
inline constexpr int kOnColour = 1;

/// How a frame of snooker is played.
struct SnookerConfig {
  int stalemate_turns = 0;  ///< > 0: that many strokes in a row with no ball potted re-rack
};

/// The Rules' description of the balls: a red 1, yellow 2, green 3, brown 4, blue 5, pink 6, black
/// 7; 0 otherwise.
int snookerValue(int id);
/// Ids 1–15.
bool isRed(int id);
/// Ids 16–21.
bool isColour(int id);

/// The balls on for the state's shooter: the reds on the table, every colour on it (kOnColour),
/// or the one colour; a free ball adds no ball here (see judgeSnooker).
std::vector<int> snookerBallsOn(const GameState& state, const std::vector<physics::Ball>& balls);

/// The points still on the table for the player at the table: 8 for each red (a red and the
/// black), 7 more when a colour is due after a red, and each colour on the table once the reds
/// are gone (27 with all six).
int pointsRemaining(const GameState& state, const std::vector<physics::Ball>& balls);

/// The points `seat` needs from penalties to win or tie the frame (Section 1, "snookers
/// required"): how far its score plus what is on the table falls short of the opponent's; 0 when
/// none are needed.
int snookersRequired(const GameState& state, const std::vector<physics::Ball>& balls, int seat);

/// Section 1, Definitions, "snookered", and Section 3, "Snookered after a Foul": the cue ball is
/// snookered when no ball of `on` can be hit on both its extreme edges by a straight stroke that no
/// other ball obstructs (cushions never snooker). False with no cue ball or no ball on.
bool isSnookered(const std::vector<physics::Ball>& balls, const std::vector<int>& on,
                 double ball_radius);

/// Section 3, "Foul and a Miss": a straight line from the cue ball reaches some part of some ball
/// of `on` unobstructed (sampled at nine points across each ball, its edges and centre included).
bool inPlainView(const std::vector<physics::Ball>& balls, const std::vector<int>& on,
                 double ball_radius);

/// Refuses what snooker has no use for (a called pocket, a declared safety, a choice carried
/// with the shot) and a nominated ball that is not a ball: 1–21, a colour when the shooter is on
/// a colour, any ball with a free ball.
Check<> checkSnookerIntent(const GameState& state, const Intent& intent);

/// A fresh frame: the breaker plays from the D at the reds.
GameState newFrame(int breaker);

/// Judges one stroke (Section 3, by its rules' titles):
/// - legal ("Play"): the cue ball first hits a ball on and nothing but balls on falls; each red
///   potted scores 1, a colour its value; a score keeps the break going, nothing ends the turn;
/// - fouls ("Fouls"): the cue ball potted or off the table, no ball hit, a ball not on hit first or
///   potted, a ball off the table, a touching ball moved (push), the shot clock; the opponent
///   scores the highest value involved, at least 4 (7 after a red for a foul before a colour is
///   nominated or hit); the opponent chooses to play on or to have the offender play again
///   (PassBack), with a free ball when snookered and the cue ball not in hand, and Replace after
///   a miss;
/// - a miss ("Foul and a Miss"): a foul in which the cue ball does not first hit a ball on, unless
/// only the
///   black is left or either player needed snookers before or after it; three in a row with a
///   ball on in plain view lose the frame (ThreeMisses);
/// - the cue ball potted or off the table comes in hand in the D ("Playing from in-Hand");
/// - colours potted while reds remain, or on a foul, or as a free ball, or off the table, are
///   re-spotted ("Spotting Colours"): their own spot, else the highest free one, else the nearest
///   free point from their own spot toward the top cushion, then toward baulk; reds are never
///   re-spotted;
/// - the frame ends when the last ball falls or, with only the black left, on the first score or
///   foul ("Play"); a tie re-spots the black and the non-breaker plays at it from the D
///   (the Rules draw lots: a program names the player instead).
/// A program is a strict referee: every failure to first hit a ball on is a miss (the exceptions
/// above aside), where a referee judges the attempt. Not judged: the jump shot (the physics
/// records no ball passed over) and a free ball that snookers the opponent.
Result<Verdict> judgeSnooker(const GameState& state, const Shot& shot, const TableContext& table,
                             const SnookerConfig& config);

/// The incoming player's answer to a foul: PlayOn and FreeBall play from the table as it lies;
/// PassBack has the offender play again from it; Replace puts the balls back where they stood
/// before the foul and the miss (GameState::before_miss) and the offender plays again.
Result<Verdict> applySnookerChoice(const GameState& state, Choice choice);

}  // namespace pool::rules
