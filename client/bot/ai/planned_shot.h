// The AI's decision for one turn: a cue shot with its call, placement and choice.
#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <string>

#include "physics/cue_strike.h"
#include "rules/game_state.h"
#include "rules/shot.h"

namespace pool::bot {

/// What kind of shot the planner settled on.
enum class ShotKind : std::uint8_t {
  Break,     ///< the opening break
  Pot,       ///< a called ball into a called pocket, verified in the physics
  Safety,    ///< a declared safety, verified legal in the physics
  Fallback,  ///< nothing verified: a declared safety at the nearest legal ball
  Choice,    ///< an answer to the rules' options that re-racks (no shot)
  Carom,     ///< three-cushion: a stroke that scores, verified in the physics
};

/// "break", "pot", "safety", "fallback", "choice", "carom"
const char* toString(ShotKind kind);

/// One turn's decision. Angles in radians, speed in m/s of the cue ball (speed_is_ball).
struct PlannedShot {
  ShotKind kind = ShotKind::Fallback;
  physics::CueShot cue;
  std::optional<int> called_ball;  ///< with called_pocket
  std::string called_pocket;       ///< pocket name; empty: none
  /// False in snooker: no pocket is called and no safety declared; the called ball is what the
  /// planner aims to pot, declared only as a nomination (`nominate`).
  bool calls_pockets = true;
  bool nominate = false;                       ///< snooker: the called ball is the nominated ball
  bool safety = false;                         ///< a declared safety
  std::optional<Eigen::Vector2d> cue_ball_at;  ///< ball in hand: place the cue ball here, m
  std::optional<rules::Choice> choice;         ///< the answer to pending options
  double value = 0.0;                          ///< the planner's score (for logs)
  /// The share of noisy tries that made the pot, when it was sampled; else empty.
  std::optional<double> success;
};

/// The shooter's declared intent for the rules (snooker: the nominated ball, if any, alone).
rules::Intent intentOf(const PlannedShot& shot);

/// True when the decision carries a stroke (everything but a re-racking choice).
bool shoots(const PlannedShot& shot);

/// One line for logs, e.g. "pot 3 in foot_left_corner at 2.10 m/s (yaw 0.412)".
std::string describe(const PlannedShot& shot);

}  // namespace pool::bot
