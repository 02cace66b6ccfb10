// Conversions between the wire types of pool.idl and domain types.
#include "net/convert.h"

#include <cmath>

#include <algorithm>
#include <optional>
#include <string>

#include "net/wire_fields.h"

namespace pool::net {

namespace {

pool_Vec3 toVec3(const physics::Vec3& v) {
  return {v.x(), v.y(), v.z()};
}

physics::Vec3 fromVec3(const pool_Vec3& v) {
  return {v.x, v.y, v.z};
}

pool_MotionState toWire(physics::MotionState s) {
  using M = physics::MotionState;
  switch (s) {
    case M::Stationary:
      return pool_MOTION_STATIONARY;
    case M::Spinning:
      return pool_MOTION_SPINNING;
    case M::Sliding:
      return pool_MOTION_SLIDING;
    case M::Rolling:
      return pool_MOTION_ROLLING;
    case M::Airborne:
      return pool_MOTION_AIRBORNE;
    case M::Pocketed:
      return pool_MOTION_POCKETED;
    case M::OffTable:
      return pool_MOTION_OFF_TABLE;
  }
  return pool_MOTION_STATIONARY;
}

std::optional<physics::MotionState> fromWire(const pool_MotionState& s) {
  using M = physics::MotionState;
  switch (rawValue(s)) {
    case pool_MOTION_STATIONARY:
      return M::Stationary;
    case pool_MOTION_SPINNING:
      return M::Spinning;
    case pool_MOTION_SLIDING:
      return M::Sliding;
    case pool_MOTION_ROLLING:
      return M::Rolling;
    case pool_MOTION_AIRBORNE:
      return M::Airborne;
    case pool_MOTION_POCKETED:
      return M::Pocketed;
    case pool_MOTION_OFF_TABLE:
      return M::OffTable;
  }
  return std::nullopt;
}

pool_ShotEventType toWire(physics::EventType t) {
  using E = physics::EventType;
  switch (t) {
    case E::Strike:
      return pool_EVENT_STRIKE;
    case E::BallBall:
      return pool_EVENT_BALL_BALL;
    case E::BallCushion:
      return pool_EVENT_BALL_CUSHION;
    case E::Pocket:
      return pool_EVENT_POCKET;
    case E::SlideToRoll:
      return pool_EVENT_SLIDE_TO_ROLL;
    case E::RollToRest:
      return pool_EVENT_ROLL_TO_REST;
    case E::SpinToRest:
      return pool_EVENT_SPIN_TO_REST;
    case E::Airborne:
      return pool_EVENT_AIRBORNE;
    case E::Land:
      return pool_EVENT_LAND;
    case E::OffTable:
      return pool_EVENT_OFF_TABLE;
    case E::Respot:
      return pool_EVENT_RESPOT;
  }
  return pool_EVENT_STRIKE;
}

std::optional<physics::EventType> fromWire(const pool_ShotEventType& t) {
  using E = physics::EventType;
  switch (rawValue(t)) {
    case pool_EVENT_STRIKE:
      return E::Strike;
    case pool_EVENT_BALL_BALL:
      return E::BallBall;
    case pool_EVENT_BALL_CUSHION:
      return E::BallCushion;
    case pool_EVENT_POCKET:
      return E::Pocket;
    case pool_EVENT_SLIDE_TO_ROLL:
      return E::SlideToRoll;
    case pool_EVENT_ROLL_TO_REST:
      return E::RollToRest;
    case pool_EVENT_SPIN_TO_REST:
      return E::SpinToRest;
    case pool_EVENT_AIRBORNE:
      return E::Airborne;
    case pool_EVENT_LAND:
      return E::Land;
    case pool_EVENT_OFF_TABLE:
      return E::OffTable;
    case pool_EVENT_RESPOT:
      return E::Respot;
  }
  return std::nullopt;
}

}  // namespace

pool_BallState toWire(const physics::Ball& ball) {
  pool_BallState b{};
  b.id = static_cast<uint8_t>(ball.id);
  b.state = toWire(ball.state);
  b.pos = toVec3(ball.pos);
  b.orient = {ball.orient.w(), ball.orient.x(), ball.orient.y(), ball.orient.z()};
  b.vel = toVec3(ball.vel);
  b.ang_vel = toVec3(ball.ang_vel);
  setText(b.pocket, ball.pocket);
  return b;
}

Result<physics::Ball> fromWire(const pool_BallState& ball) {
  if (ball.id > physics::kMaxBallId) {
    return Result<physics::Ball>::fail("ball id " + std::to_string(ball.id) + " is not in 0-21");
  }
  const auto state = fromWire(ball.state);
  if (!state) {
    return Result<physics::Ball>::fail("unknown motion state " +
                                       std::to_string(rawValue(ball.state)));
  }
  physics::Ball b;
  b.id = ball.id;
  b.state = *state;
  b.pos = fromVec3(ball.pos);
  b.orient = physics::Quat(ball.orient.w, ball.orient.x, ball.orient.y, ball.orient.z);
  b.vel = fromVec3(ball.vel);
  b.ang_vel = fromVec3(ball.ang_vel);
  b.pocket = std::string(textOf(ball.pocket));
  return Result<physics::Ball>::ok(std::move(b));
}

pool_ShotEvent toWire(const physics::Event& event) {
  pool_ShotEvent e{};
  e.t = event.t;
  e.type = toWire(event.type);
  e.ball_a = static_cast<int16_t>(event.ball_a);
  e.ball_b = static_cast<int16_t>(event.ball_b);
  setText(e.where, event.where);
  e.speed = event.speed;
  e.pos = toVec3(event.pos);
  return e;
}

Result<physics::Event> fromWire(const pool_ShotEvent& event) {
  const auto type = fromWire(event.type);
  if (!type) {
    return Result<physics::Event>::fail("unknown event type " +
                                        std::to_string(rawValue(event.type)));
  }
  // A shot's events lie within its simulated time (physics: 60 s at most by default): a time
  // past any shot would make a replay of hours of frames.
  constexpr double kLatestEvent = 120.0;
  if (!std::isfinite(event.t) || event.t < 0.0 || event.t > kLatestEvent) {
    return Result<physics::Event>::fail("event time out of range (0 to 120 s)");
  }
  physics::Event e;
  e.t = event.t;
  e.type = *type;
  e.ball_a = event.ball_a;
  e.ball_b = event.ball_b;
  e.where = std::string(textOf(event.where));
  e.speed = event.speed;
  e.pos = fromVec3(event.pos);
  return Result<physics::Event>::ok(std::move(e));
}

bool putBalls(dds_sequence_pool_BallState& seq, std::span<const physics::Ball> balls) {
  const auto n = static_cast<std::uint32_t>(std::min<std::size_t>(balls.size(), pool_MAX_BALLS));
  auto out = resizeSequence(seq, n);
  std::transform(balls.begin(), balls.begin() + n, out.begin(),
                 [](const physics::Ball& b) { return toWire(b); });
  return n == balls.size();
}

Result<std::vector<physics::Ball>> getBalls(const dds_sequence_pool_BallState& seq) {
  std::vector<physics::Ball> balls;
  for (const pool_BallState& b : elementsOf(seq)) {
    auto ball = fromWire(b);
    if (!ball) {
      return Result<std::vector<physics::Ball>>::fail("balls[" + std::to_string(balls.size()) +
                                                      "]: " + ball.error());
    }
    balls.push_back(std::move(*ball));
  }
  return Result<std::vector<physics::Ball>>::ok(std::move(balls));
}

bool putEvents(dds_sequence_pool_ShotEvent& seq, std::span<const physics::Event> events) {
  const auto n = static_cast<std::uint32_t>(std::min<std::size_t>(events.size(), pool_MAX_EVENTS));
  auto out = resizeSequence(seq, n);
  std::transform(events.begin(), events.begin() + n, out.begin(),
                 [](const physics::Event& e) { return toWire(e); });
  return n == events.size();
}

Result<physics::EventLog> getEvents(const dds_sequence_pool_ShotEvent& seq) {
  physics::EventLog events;
  for (const pool_ShotEvent& e : elementsOf(seq)) {
    auto event = fromWire(e);
    if (!event) {
      return Result<physics::EventLog>::fail("events[" + std::to_string(events.size()) +
                                             "]: " + event.error());
    }
    events.push_back(std::move(*event));
  }
  return Result<physics::EventLog>::ok(std::move(events));
}

pool_ShotOption toWire(protocol::ShotOption option) {
  switch (option) {
    case protocol::ShotOption::None:
      return pool_OPTION_NONE;
    case protocol::ShotOption::PlayOn:
      return pool_OPTION_PLAY_ON;
    case protocol::ShotOption::BallInHand:
      return pool_OPTION_BALL_IN_HAND;
    case protocol::ShotOption::RespotEight:
      return pool_OPTION_RESPOT_EIGHT;
    case protocol::ShotOption::ReBreak:
      return pool_OPTION_REBREAK;
    case protocol::ShotOption::OpponentReBreaks:
      return pool_OPTION_OPPONENT_REBREAKS;
    case protocol::ShotOption::PushOut:
      return pool_OPTION_PUSH_OUT;
    case protocol::ShotOption::PassBack:
      return pool_OPTION_PASS_BACK;
    case protocol::ShotOption::FreeBall:
      return pool_OPTION_FREE_BALL;
    case protocol::ShotOption::Replace:
      return pool_OPTION_REPLACE;
  }
  return pool_OPTION_NONE;
}

Result<protocol::ShotOption> fromWire(const pool_ShotOption& option) {
  switch (rawValue(option)) {
    case pool_OPTION_NONE:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::None);
    case pool_OPTION_PLAY_ON:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::PlayOn);
    case pool_OPTION_BALL_IN_HAND:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::BallInHand);
    case pool_OPTION_RESPOT_EIGHT:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::RespotEight);
    case pool_OPTION_REBREAK:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::ReBreak);
    case pool_OPTION_OPPONENT_REBREAKS:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::OpponentReBreaks);
    case pool_OPTION_PUSH_OUT:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::PushOut);
    case pool_OPTION_PASS_BACK:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::PassBack);
    case pool_OPTION_FREE_BALL:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::FreeBall);
    case pool_OPTION_REPLACE:
      return Result<protocol::ShotOption>::ok(protocol::ShotOption::Replace);
  }
  return Result<protocol::ShotOption>::fail("unknown shot option " +
                                            std::to_string(rawValue(option)));
}

Sample<pool_ShotCommand> toWire(const protocol::ShotRequest& request) {
  Sample<pool_ShotCommand> sample;
  pool_ShotCommand& c = *sample;
  setText(c.match, request.match);
  c.seat = static_cast<int16_t>(request.seat);
  c.seat_token = request.seat_token;
  c.seq = request.seq;
  c.yaw = request.cue.yaw;
  c.tip_side = request.cue.tip_side;
  c.tip_height = request.cue.tip_height;
  c.elevation = request.cue.elevation;
  c.speed = request.cue.speed;
  c.speed_is_ball = request.cue.speed_is_ball;
  c.called_ball = static_cast<int16_t>(request.called_ball.value_or(-1));
  setText(c.called_pocket, request.called_pocket);
  c.safety = request.safety;
  c.has_cue_ball_placement = request.cue_ball_at.has_value();
  c.cue_ball_x = request.cue_ball_at ? request.cue_ball_at->x() : 0.0;
  c.cue_ball_y = request.cue_ball_at ? request.cue_ball_at->y() : 0.0;
  c.option = toWire(request.option);
  const auto n = static_cast<std::uint32_t>(std::min<std::size_t>(request.signature.size(), 64));
  auto signature = resizeSequence(c.signature, n);
  std::copy_n(request.signature.begin(), n, signature.begin());
  return sample;
}

Result<protocol::ShotRequest> fromWire(const pool_ShotCommand& command) {
  const auto option = fromWire(command.option);
  if (!option) {
    return Result<protocol::ShotRequest>::fail(option.error());
  }
  protocol::ShotRequest r;
  r.match = std::string(textOf(command.match));
  r.seat = command.seat;
  r.seat_token = command.seat_token;
  r.seq = command.seq;
  r.cue = {command.yaw,       command.tip_side, command.tip_height,
           command.elevation, command.speed,    command.speed_is_ball};
  if (command.called_ball >= 0) {
    r.called_ball = command.called_ball;
  }
  r.called_pocket = std::string(textOf(command.called_pocket));
  r.safety = command.safety;
  if (command.has_cue_ball_placement) {
    r.cue_ball_at = Eigen::Vector2d(command.cue_ball_x, command.cue_ball_y);
  }
  r.option = *option;
  const auto signature = elementsOf(command.signature);
  r.signature.assign(signature.begin(), signature.end());
  return Result<protocol::ShotRequest>::ok(std::move(r));
}

}  // namespace pool::net
