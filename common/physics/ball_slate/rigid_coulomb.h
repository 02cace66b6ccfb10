// A ball against a fixed surface (slate, or a cushion nose in Han's model): restitution and
// Coulomb friction as one rigid impulse.
#pragma once

#include "physics/ball.h"

namespace pool::physics {

/// Resolves a ball striking a fixed contact. `normal` is the unit vector from the contact point
/// to the ball's centre; the contact point is at centre − R·normal. The normal impulse gives
/// back `restitution` of the approach speed; the tangential impulse stops the contact point's
/// slip if that needs at most `friction` times the normal impulse, otherwise it is that limit
/// against the slip (Coulomb). This is Han (2005)'s cushion model in vector form (sticking and
/// sliding cases), used with the nose geometry of the cushion. Returns the approach speed
/// (m/s, > 0), or 0 if the ball was not approaching (then nothing changes).
double resolveFixedContact(Vec3& vel, Vec3& ang_vel, const Vec3& normal, double restitution,
                           double friction, double radius, double mass);

}  // namespace pool::physics
