// Seeded Gaussian aim and speed error.
#include "client/bot/ai/skill_noise.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace pool::bot {

std::uint64_t Rng::next() {
  return rng_.next();
}

double Rng::uniform() {
  return rng_.uniform();
}

double Rng::gaussian() {
  const double u1 = 1.0 - uniform();  // (0, 1]: the log stays finite
  const double u2 = uniform();
  const double g = std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  return std::clamp(g, -3.0, 3.0);
}

SkillNoise::SkillNoise(double skill, std::uint64_t seed)
    : yaw_sigma_((1.0 - std::clamp(skill, 0.0, 1.0)) * kYawSigmaAtZero),
      speed_sigma_((1.0 - std::clamp(skill, 0.0, 1.0)) * kSpeedSigmaAtZero),
      rng_(seed) {}

physics::CueShot SkillNoise::apply(const physics::CueShot& shot, double max_speed) {
  physics::CueShot out = shot;
  // Draw both every time so the sequence does not depend on the skill.
  const double yaw_error = rng_.gaussian();
  const double speed_error = rng_.gaussian();
  out.yaw += yaw_sigma_ * yaw_error;
  out.speed = std::min(max_speed, out.speed * (1.0 + speed_sigma_ * speed_error));
  return out;
}

}  // namespace pool::bot
