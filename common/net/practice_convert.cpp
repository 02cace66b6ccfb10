// Practice commands to and from their wire type, with the checks of their fields.
#include "net/practice_convert.h"

#include <algorithm>

#include "net/shot_command_check.h"
#include "net/wire_fields.h"

namespace pool::net {

namespace {

static_assert(pool_PRACTICE_LAYOUT == static_cast<int>(protocol::PracticeAction::Layout));
static_assert(pool_PRACTICE_RACK == static_cast<int>(protocol::PracticeAction::Rack));
static_assert(pool_PRACTICE_UNDO == static_cast<int>(protocol::PracticeAction::Undo));
static_assert(pool_PRACTICE_AGAIN == static_cast<int>(protocol::PracticeAction::Again));
static_assert(pool_PRACTICE_PHYSICS == static_cast<int>(protocol::PracticeAction::Physics));
static_assert(sizeof(pool_PracticeCommand::coefficients) / sizeof(double) ==
              protocol::kPracticeCoefficients.size());
static_assert(pool_MAX_BALLS == protocol::kPracticeMaxBalls);  // a layout's balls fit the sequence

}  // namespace

Sample<pool_PracticeCommand> toWire(const protocol::PracticeRequest& r) {
  Sample<pool_PracticeCommand> sample;
  pool_PracticeCommand& c = *sample;
  setText(c.match, r.match);
  c.seat = static_cast<std::int16_t>(r.seat);
  c.seat_token = r.seat_token;
  c.seq = r.seq;
  setRawValue(c.action, static_cast<std::int32_t>(r.action));
  const auto n = static_cast<std::uint32_t>(std::min(r.balls.size(), protocol::kPracticeMaxBalls));
  auto balls = resizeSequence(c.balls, n);
  for (std::uint32_t i = 0; i < n; ++i) {
    balls[i].id = static_cast<std::uint8_t>(r.balls[i].id);
    balls[i].x = r.balls[i].x;
    balls[i].y = r.balls[i].y;
  }
  c.rack = static_cast<std::uint8_t>(r.rack);
  std::copy(r.coefficients.begin(), r.coefficients.end(), c.coefficients);
  setBytes(c.signature, r.signature, 64);
  return sample;
}

IncomingPractice readPractice(const pool_PracticeCommand& c,
                              const protocol::CommandLimits& limits) {
  IncomingPractice in;
  in.match = std::string(textOf(c.match));
  in.seat = c.seat;
  in.seq = c.seq;
  const auto fail = [&](std::string problem) {
    in.problem = std::move(problem);
    return in;
  };
  if (CommandCheck check = checkMatchAndSeat(c); !check.ok()) return fail(check.error());
  const std::int32_t action = rawValue(c.action);
  if (action < pool_PRACTICE_LAYOUT || action > pool_PRACTICE_PHYSICS) {
    return fail("action: not a known practice action");
  }
  const auto balls = elementsOf(c.balls);
  if (balls.size() > protocol::kPracticeMaxBalls) {
    return fail("balls: at most " + std::to_string(protocol::kPracticeMaxBalls));
  }
  protocol::PracticeRequest r;
  r.match = in.match;
  r.seat = c.seat;
  r.seat_token = c.seat_token;
  r.seq = c.seq;
  r.action = static_cast<protocol::PracticeAction>(action);
  for (const auto& b : balls) r.balls.push_back({b.id, b.x, b.y});
  r.rack = c.rack;
  std::copy(std::begin(c.coefficients), std::end(c.coefficients), r.coefficients.begin());
  if (auto why = protocol::checkPracticeFields(r, limits.half_length, limits.half_width); !why) {
    return fail(why.error());
  }
  if (c.signature._length > 64 || (c.signature._length > 0 && !c.signature._buffer)) {
    in.bad_signature = true;
    return fail("signature: at most 64 bytes");
  }
  const auto signature = elementsOf(c.signature);
  r.signature.assign(signature.begin(), signature.end());
  in.request = std::move(r);
  return in;
}

}  // namespace pool::net
