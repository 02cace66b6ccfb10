// Every physics coefficient of a table, under the names of SIM-CONTRACT.md, with docs/PHYSICS.md's
// defaults.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/check.h"

namespace pool::table {

/// The coefficients the physics reads. Units SI; defaults are docs/PHYSICS.md's typical values.
struct PhysicsParams {
  double u_s = 0.2;           ///< ball–cloth sliding friction
  double u_r = 0.01;          ///< rolling resistance: a rolling ball slows at u_r·g
  double spin_decel = 10.9;   ///< vertical-axis spin deceleration, rad/s²
  double e_b = 0.95;          ///< ball–ball restitution
  std::optional<double> u_b;  ///< ball–ball friction; empty = speed-dependent model (Alciatore)
  double e_c = 0.85;          ///< ball–cushion restitution
  double u_c = 0.2;           ///< ball–cushion friction
  double e_slate = 0.5;       ///< ball–slate restitution (bounces after a jump)
  double cushion_height = 0.635 * 2 * 0.028575;  ///< cushion nose above the slate, m
  double ball_mass = 0.170097;                   ///< kg
  double ball_radius = 0.028575;                 ///< m
  double cue_mass = 0.567;                       ///< kg
  double cue_end_mass = 0.0085;                  ///< cue tip's effective end mass (squirt), kg
  double miscue_limit = 0.5;                     ///< largest tip offset, fraction of R
};

/// The names setParam accepts, in SIM-CONTRACT.md's order.
const std::vector<std::string_view>& paramNames();

/// Sets the coefficient called `name` to `value`, or refuses with a one-line reason without the
/// field name, e.g. "must be a finite number in (0, 2]" ("out_of_range") or "unknown parameter"
/// ("unknown_parameter"). Nothing changes on a refusal.
Check<> setParam(PhysicsParams& params, std::string_view name, double value);

/// Checks the whole set for consistency (each value in range, cushion nose above the ball's
/// centre and below its top), or refuses it with "<name>: <reason>".
Check<> validate(const PhysicsParams& params);

}  // namespace pool::table
