// Test helpers for the rules: a 9-ft table, ball layouts and a builder of synthetic event logs.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "physics/ball.h"
#include "physics/events.h"
#include "rules/eight_ball.h"
#include "rules/shot.h"
#include "rules/table_context.h"

namespace pool::rules::test {

constexpr double kR = 0.028575;

/// A 9-ft table (the spec's defaults) as the rules see it.
inline TableContext nineFoot() {
  table::TableSpec spec;
  spec.name = "test-9ft";
  return tableContext(spec);
}

/// A ball at rest at (x, y).
inline physics::Ball ballAt(int id, double x, double y) {
  physics::Ball b;
  b.id = id;
  b.pos = physics::Vec3(x, y, kR);
  return b;
}

/// The cue ball behind the head string and all fifteen object balls in a triangle from the foot
/// spot.
inline std::vector<physics::Ball> rackLayout() {
  std::vector<physics::Ball> balls{ballAt(0, -0.80, 0.0)};
  int id = 1;
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      double x = 0.635 + row * 2 * kR * 0.8661;
      double y = (k - row / 2.0) * 2.01 * kR;
      balls.push_back(ballAt(id++, x, y));
    }
  }
  return balls;
}

/// Balls `ids` spread on the table in front of the head string (y rows), the cue ball at (x0, 0).
inline std::vector<physics::Ball> spreadLayout(const std::vector<int>& ids, double cue_x = -0.3) {
  std::vector<physics::Ball> balls{ballAt(0, cue_x, 0.0)};
  int k = 0;
  for (int id : ids) {
    balls.push_back(ballAt(id, 0.2 + 0.15 * (k % 6), -0.45 + 0.18 * (k / 6)));
    ++k;
  }
  return balls;
}

/// Marks an event position the builder leaves to makeShot.
constexpr double kUnset = 1e9;

/// Builds a log in time order: a strike at t = 0, then each event `dt` later than the last.
class LogBuilder {
 public:
  explicit LogBuilder(double dt = 0.05) : LogBuilder(physics::kCueBall, dt) {}
  /// A log that starts with the strike of ball `struck` (three-cushion: the shooter's own ball).
  static LogBuilder striking(int struck) { return LogBuilder(struck, 0.05); }

  LogBuilder& hit(int a, int b) { return add(physics::EventType::BallBall, a, b, ""); }
  LogBuilder& cushion(int id, std::string name = "foot", double x = 0.0) {
    add(physics::EventType::BallCushion, id, -1, std::move(name));
    log_.back().pos = physics::Vec3(x, 0.0, kR);
    return *this;
  }
  LogBuilder& pocket(int id, std::string name) {
    return add(physics::EventType::Pocket, id, -1, std::move(name));
  }
  LogBuilder& offTable(int id) { return add(physics::EventType::OffTable, id, -1, ""); }
  LogBuilder& rest(int id) { return add(physics::EventType::RollToRest, id, -1, ""); }
  LogBuilder& airborne(int id) { return add(physics::EventType::Airborne, id, -1, ""); }
  LogBuilder& respot(int id) { return add(physics::EventType::Respot, id, -1, "watchdog"); }
  /// Any event, appended as given (its time is kept).
  LogBuilder& raw(physics::Event e) {
    log_.push_back(std::move(e));
    return *this;
  }
  physics::EventLog build() const { return log_; }

 private:
  LogBuilder& add(physics::EventType type, int a, int b, std::string where) {
    physics::Event e;
    e.t = log_.empty() ? 0.0 : log_.back().t + dt_;
    e.type = type;
    e.ball_a = a;
    e.ball_b = b;
    e.where = std::move(where);
    e.pos = physics::Vec3::Constant(kUnset);
    log_.push_back(std::move(e));
    return *this;
  }

  LogBuilder(int struck, double dt) : dt_(dt) {
    add(physics::EventType::Strike, struck, -1, "");
    log_.back().t = 0.0;
  }

  double dt_;
  physics::EventLog log_;
};

/// The balls after a log: pocketed and off-table balls marked so, the rest where they were.
inline std::vector<physics::Ball> applyLog(std::vector<physics::Ball> balls,
                                           const physics::EventLog& log) {
  for (const auto& e : log) {
    for (auto& b : balls) {
      if (b.id != e.ball_a) continue;
      if (e.type == physics::EventType::Pocket) {
        b.state = physics::MotionState::Pocketed;
        b.pocket = e.where;
      }
      if (e.type == physics::EventType::OffTable) b.state = physics::MotionState::OffTable;
    }
  }
  return balls;
}

/// Where an event without an explicit position happened: where its ball lay before the shot; for
/// the cue ball hitting a ball, where that ball lay (the cue ball is within a ball's width of it).
inline physics::Vec3 eventPos(const physics::Event& e, const std::vector<physics::Ball>& before) {
  int id = e.type == physics::EventType::BallBall && e.ball_a == 0 ? e.ball_b : e.ball_a;
  for (const auto& b : before) {
    if (b.id == id) return b.pos;
  }
  return physics::Vec3::Zero();
}

/// A shot from balls before, an intent and a log; the balls after follow from the log.
inline Shot makeShot(const std::vector<physics::Ball>& before, Intent intent,
                     const LogBuilder& log) {
  Shot shot;
  shot.before = before;
  shot.intent = std::move(intent);
  shot.events = log.build();
  for (auto& e : shot.events) {
    if (e.pos.x() == kUnset) e.pos = eventPos(e, before);
  }
  shot.after = applyLog(before, shot.events);
  return shot;
}

/// Marks balls as already pocketed (before a shot).
inline std::vector<physics::Ball> withPocketed(std::vector<physics::Ball> balls,
                                               const std::vector<int>& ids) {
  for (auto& b : balls) {
    for (int id : ids) {
      if (b.id == id) b.state = physics::MotionState::Pocketed;
    }
  }
  return balls;
}

/// A state after the break with the table open, `shooter` to shoot.
inline GameState openTable(int shooter = 0) {
  GameState state = newRack(1 - shooter);
  state.phase = Phase::Open;
  state.shooter = shooter;
  state.ball_in_hand = BallInHand::None;
  return state;
}

/// Groups assigned: seat 0 solids, seat 1 stripes; `shooter` to shoot.
inline GameState assigned(int shooter = 0) {
  GameState state = openTable(shooter);
  state.phase = Phase::Assigned;
  state.groups = {Group::Solids, Group::Stripes};
  return state;
}

/// Judges a shot that must not be refused.
inline Verdict judged(const GameState& state, const Shot& shot,
                      const EightBallConfig& config = {}) {
  auto verdict = judgeEightBall(state, shot, nineFoot(), config);
  EXPECT_TRUE(verdict.hasValue()) << verdict.error();
  return verdict ? *verdict : Verdict{};
}

/// The reason a shot is refused ("" if it was judged).
inline std::string refusal(const GameState& state, const Shot& shot,
                           const EightBallConfig& config = {}) {
  auto verdict = judgeEightBall(state, shot, nineFoot(), config);
  return verdict ? "" : verdict.error();
}

}  // namespace pool::rules::test
