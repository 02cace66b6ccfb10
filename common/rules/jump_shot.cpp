// Snooker's jump shot: the cue ball's flights before its first contact, against the balls standing.
#include "rules/jump_shot.h"

#include <algorithm>
#include <optional>

#include "table/segment_distance.h"

namespace pool::rules {
namespace {

using Vec2 = Eigen::Vector2d;
using table::segmentDistance;

const physics::Ball* standing(const Shot& shot, int id) {
  for (const auto& b : shot.before) {
    if (b.id == id && physics::onTable(b.state)) return &b;
  }
  return nullptr;
}

// Whether the flight's leg from `a` to `b` passes over a standing object ball other than `except`
// (a ball the leg starts against, within a millimetre, and leaves behind it is not passed over).
bool legPassesOver(const Shot& shot, const Vec2& a, const Vec2& b, double r, int except = -1) {
  constexpr double kAgainst = 1e-3;
  return std::any_of(shot.before.begin(), shot.before.end(), [&](const physics::Ball& ball) {
    if (ball.id == physics::kCueBall || ball.id == except || !physics::onTable(ball.state))
      return false;
    const Vec2 c = ball.pos.head<2>();
    if ((c - a).norm() < 2.0 * r + kAgainst && (c - a).dot(b - a) <= 0.0) return false;
    return segmentDistance(c, a, b) < 2.0 * r - 1e-9;
  });
}

// The cue ball's next landing (or end of flight) after event `i`.
std::optional<Vec2> landingAfter(const physics::EventLog& events, std::size_t i) {
  for (std::size_t j = i + 1; j < events.size(); ++j) {
    const auto& e = events[j];
    if (e.ball_a != physics::kCueBall) continue;
    if (e.type == physics::EventType::Land || e.type == physics::EventType::OffTable ||
        e.type == physics::EventType::Pocket)
      return e.pos.head<2>();
  }
  return std::nullopt;
}

}  // namespace

bool jumpedOverABall(const Shot& shot, double ball_radius) {
  const double r = ball_radius;
  std::optional<Vec2> from;  // where the cue ball's current leg in the air began
  for (std::size_t i = 0; i < shot.events.size(); ++i) {
    const physics::Event& e = shot.events[i];
    const bool cue_a = e.ball_a == physics::kCueBall;
    if (e.type == physics::EventType::BallBall && (cue_a || e.ball_b == physics::kCueBall)) {
      // The first contact: on the cloth, nothing after it is a jump shot (exception i).
      if (!from) return false;
      const int struck = cue_a ? e.ball_b : e.ball_a;
      const physics::Ball* ball = standing(shot, struck);
      if (!ball) return false;
      const Vec2 at = ball->pos.head<2>();
      const Vec2 heading = at - *from;
      if (heading.norm() <= 0.0) return false;
      const Vec2 dir = heading.normalized();
      // The cue ball's centre at the contact: the event's position when it is ball_a; else a
      // ball's width short of the struck ball along the flight.
      const Vec2 contact = cue_a ? Vec2(e.pos.head<2>()) : Vec2(at - 2.0 * r * dir);
      // Over another ball on the way to this one?
      if (legPassesOver(shot, *from, contact, r, struck)) return true;
      // Struck in the air: a jump shot only when the cue ball then passes over it, its centre
      // over the struck ball's, and lands on its far side (exception ii); a thin hit that flies
      // on beside it is not one.
      const auto land = landingAfter(shot.events, i);
      return land && segmentDistance(at, contact, *land) < r && (*land - at).dot(dir) > 0.0;
    }
    if (!cue_a) continue;
    switch (e.type) {
      case physics::EventType::Airborne:
        from = e.pos.head<2>();
        break;
      case physics::EventType::BallCushion:
        if (from) {
          if (legPassesOver(shot, *from, e.pos.head<2>(), r)) return true;
          from = e.pos.head<2>();
        }
        break;
      case physics::EventType::Land:
      case physics::EventType::OffTable:
      case physics::EventType::Pocket:
        if (from && legPassesOver(shot, *from, e.pos.head<2>(), r)) return true;
        from.reset();
        break;
      default:
        break;
    }
  }
  return false;
}

}  // namespace pool::rules
