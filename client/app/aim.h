// The shot being aimed: cue heading, tip offset, elevation, power, call, cue-ball placement and the
// answer to a pending choice; kept inside the server's command limits, and turned into a command.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>

#include "protocol/command_limits.h"
#include "protocol/shot_request.h"

namespace pool::app {

/// The call that goes with a shot: a ball and a pocket, snooker's nominated ball alone, or a
/// safety.
struct ShotCall {
  std::optional<int> ball;  ///< 1–21
  std::string pocket;       ///< a pocket name (rules::pocketNames); with `ball`; snooker: empty
  bool safety = false;      ///< a declared safety (no ball, no pocket)
  bool by_player = false;   ///< chosen by the player: the automatic call leaves it alone

  bool operator==(const ShotCall&) const = default;
};

/// Slowest cue the power bar gives (power 0), m/s.
inline constexpr double kMinCueSpeed = 0.3;

/// Everything the player sets before shooting. Angles in radians, tip in fractions of R.
struct AimState {
  double yaw = 0.0;         ///< cue heading in the table plane, (-pi, pi], 0 = +x
  double tip_side = 0.0;    ///< right of centre, seen from behind
  double tip_height = 0.0;  ///< above centre
  double elevation = 0.0;   ///< cue above horizontal
  double power = 0.0;       ///< 0–1 of the power bar
  /// A mouse stroke under way: how far the cue is drawn back from the struck point, m.
  std::optional<double> stroke_back;
  std::optional<Eigen::Vector2d> cue_ball_at;  ///< ball in hand: where the cue ball goes, m
  ShotCall call;
  protocol::ShotOption option = protocol::ShotOption::None;
};

/// Keeps `aim`'s numbers inside `limits`: yaw wrapped to (-pi, pi], the tip inside the miscue
/// circle (scaled back along its direction), elevation in [0, max], power in [0, 1].
void clampAim(AimState& aim, const protocol::CommandLimits& limits);

/// Cue speed of power `power` (0–1), m/s: kMinCueSpeed to the limit's max_speed.
double cueSpeedOf(double power, const protocol::CommandLimits& limits);
/// The power (0–1) that gives cue speed `speed` (m/s), the inverse of cueSpeedOf (clamped).
double powerOfSpeed(double speed, const protocol::CommandLimits& limits);

/// The command for `aim` (match, seat, token and sequence are the client's to fill in): the cue's
/// speed from the power, the call (none with a safety; a ball without a pocket is snooker's
/// nomination), the placement and the option.
protocol::ShotRequest requestOf(const AimState& aim, const protocol::CommandLimits& limits);

}  // namespace pool::app
