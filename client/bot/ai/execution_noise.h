// A player's execution error as Gaussian noise on each of a stroke's five parameters.
#pragma once

#include "client/bot/ai/skill_noise.h"
#include "physics/cue_strike.h"

namespace pool::bot {

/// Standard deviations of a stroke's errors.
struct ExecutionNoise {
  double yaw = 0.0;        ///< aim, rad
  double elevation = 0.0;  ///< cue elevation, rad
  double speed = 0.0;      ///< m/s
  double tip = 0.0;        ///< each tip offset, fraction of R
};

/// The noise of the computer-olympiad billiards tournaments (Greenspan, Ken and others, "The
/// 2008 computational pool tournament", ICGA Journal 31(4): σ of 0.125° on the aim, 0.1° on the
/// elevation, 0.075 m/s on the speed and 0.5 mm on each tip offset): a strong human player.
ExecutionNoise olympiadNoise(double ball_radius);

/// `shot` with each parameter moved by a draw of its noise (clamped to ±3 σ by Rng::gaussian);
/// the elevation never below 0.
physics::CueShot perturbed(const physics::CueShot& shot, const ExecutionNoise& noise, Rng& rng);

}  // namespace pool::bot
