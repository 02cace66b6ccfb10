// Glicko-2's update, step by step as Glickman's example numbers them (steps 2 to 8).
#include "server/rating/glicko2.h"

#include <cmath>
#include <numbers>

namespace pool::rating {
namespace {

constexpr double kScale = 173.7178;    // Glicko-2's conversion of the Glicko scale (step 2)
constexpr double kConvergence = 1e-6;  // ε of the volatility's iteration (step 5)

double g(double phi) {
  return 1.0 / std::sqrt(1.0 + 3.0 * phi * phi / (std::numbers::pi * std::numbers::pi));
}

double expected(double mu, double mu_j, double phi_j) {
  return 1.0 / (1.0 + std::exp(-g(phi_j) * (mu - mu_j)));
}

// Step 5: the new volatility, by the Illinois algorithm on f(x) = 0.
double newVolatility(double phi, double sigma, double v, double delta, double tau) {
  const double a = std::log(sigma * sigma);
  const auto f = [&](double x) {
    const double ex = std::exp(x);
    const double d = phi * phi + v + ex;
    return ex * (delta * delta - phi * phi - v - ex) / (2.0 * d * d) - (x - a) / (tau * tau);
  };
  double A = a;
  double B = 0.0;
  if (delta * delta > phi * phi + v) {
    B = std::log(delta * delta - phi * phi - v);
  } else {
    int k = 1;
    while (f(a - k * tau) < 0.0) ++k;
    B = a - k * tau;
  }
  double fA = f(A);
  double fB = f(B);
  while (std::abs(B - A) > kConvergence) {
    const double C = A + (A - B) * fA / (fB - fA);
    const double fC = f(C);
    if (fC * fB <= 0.0) {
      A = B;
      fA = fB;
    } else {
      fA /= 2.0;
    }
    B = C;
    fB = fC;
  }
  return std::exp(A / 2.0);
}

}  // namespace

Rating updated(const Rating& player, std::span<const GameResult> games, double tau) {
  const double mu = (player.rating - 1500.0) / kScale;
  const double phi = player.deviation / kScale;
  const double sigma = player.volatility;
  if (games.empty()) {
    return {player.rating, kScale * std::sqrt(phi * phi + sigma * sigma), sigma};
  }
  // Steps 3 and 4: the estimated variance v and improvement Δ from the games.
  double inv_v = 0.0;
  double sum = 0.0;
  for (const GameResult& game : games) {
    const double mu_j = (game.opponent.rating - 1500.0) / kScale;
    const double phi_j = game.opponent.deviation / kScale;
    const double e = expected(mu, mu_j, phi_j);
    inv_v += g(phi_j) * g(phi_j) * e * (1.0 - e);
    sum += g(phi_j) * (game.score - e);
  }
  const double v = 1.0 / inv_v;
  const double delta = v * sum;
  // Steps 5 to 8.
  const double sigma_new = newVolatility(phi, sigma, v, delta, tau);
  const double phi_star = std::sqrt(phi * phi + sigma_new * sigma_new);
  const double phi_new = 1.0 / std::sqrt(1.0 / (phi_star * phi_star) + 1.0 / v);
  const double mu_new = mu + phi_new * phi_new * sum;
  return {kScale * mu_new + 1500.0, kScale * phi_new, sigma_new};
}

std::pair<Rating, Rating> afterMatch(const Rating& winner, const Rating& loser, double tau) {
  const GameResult won{loser, 1.0};
  const GameResult lost{winner, 0.0};
  return {updated(winner, std::span(&won, 1), tau), updated(loser, std::span(&lost, 1), tau)};
}

}  // namespace pool::rating
