// Ball–ball model after Alciatore: restitution and friction (throw, spin transfer) with his
// speed-dependent friction (TP A-14).
#pragma once

#include <optional>

#include "physics/ball.h"

namespace pool::physics {

/// Ball–ball friction as a function of the contact points' relative sliding speed (m/s):
/// 0.00995 + 0.108·exp(−1.088·v), Alciatore's fit to measured throw (TP A-14).
double alciatoreFriction(double sliding_speed);

/// Resolves a collision of balls a and b (equal mass and radius) touching at centres pa, pb.
/// Normal impulse from the restitution e; tangential impulse stops the contact points' slip if
/// friction allows, otherwise it is μ times the normal impulse against the slip, with μ the
/// constant `friction` if given, else alciatoreFriction(slip). Returns the approach speed along
/// the line of centres (m/s), or 0 if they were not approaching (then nothing changes).
double resolveBallBall(const Vec3& pa, Vec3& va, Vec3& wa, const Vec3& pb, Vec3& vb, Vec3& wb,
                       double restitution, std::optional<double> friction, double radius,
                       double mass);

}  // namespace pool::physics
