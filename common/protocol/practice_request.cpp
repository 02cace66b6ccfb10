// Practice commands: their names, signed bytes, field checks and the coefficients they set.
#include "protocol/practice_request.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <set>

#include "rules/game_rules.h"

namespace pool::protocol {

const char* toString(PracticeAction action) {
  switch (action) {
    case PracticeAction::Layout:
      return "layout";
    case PracticeAction::Rack:
      return "rack";
    case PracticeAction::Undo:
      return "undo";
    case PracticeAction::Again:
      return "again";
    case PracticeAction::Physics:
      return "physics";
  }
  return "unknown";
}

namespace {

// "8, 9, 10, 3, 22": every game's number, in the lobby's order.
std::string rackNumbers() {
  std::string out;
  for (const rules::GameInfo& g : rules::allGames()) {
    out += (out.empty() ? "" : ", ") + std::to_string(g.number);
  }
  return out;
}

}  // namespace

PracticeCoefficients coefficientsOf(const table::PhysicsParams& p) {
  return {p.u_s, p.u_r, p.spin_decel, p.e_b, p.e_c, p.u_c, p.e_slate};
}

Result<table::PhysicsParams> withCoefficients(const table::PhysicsParams& base,
                                              const PracticeCoefficients& values) {
  table::PhysicsParams out = base;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const std::string_view name = kPracticeCoefficients[i];
    if (auto ok = table::setParam(out, name, values[i]); !ok) {
      return Result<table::PhysicsParams>::fail(std::string(name) + ": " + ok.error());
    }
  }
  if (auto ok = table::validate(out); !ok) return Result<table::PhysicsParams>::fail(ok.error());
  return Result<table::PhysicsParams>::ok(out);
}

std::vector<std::uint8_t> signedBytes(const PracticeRequest& r) {
  SignedEncoder e({MessageTag::Practice, r.match, r.seat, r.seat_token, r.seq});
  e.u8(static_cast<std::uint8_t>(r.action));
  e.u8(static_cast<std::uint8_t>(r.rack));
  const std::size_t count = std::min(r.balls.size(), kPracticeMaxBalls);
  e.u8(static_cast<std::uint8_t>(count));
  // The fixed slots, then one for each ball past them: a pool layout encodes as it always did.
  for (std::size_t i = 0; i < std::max(count, kPracticeFixedSlots); ++i) {
    const BallSpot spot = i < count ? r.balls[i] : BallSpot{};
    e.u8(static_cast<std::uint8_t>(spot.id));
    e.f64(spot.x);
    e.f64(spot.y);
  }
  for (double c : r.coefficients) e.f64(c);
  assert(e.message().size() ==
         kSignedPracticeBytes +
             (count > kPracticeFixedSlots ? count - kPracticeFixedSlots : 0) * kPracticeSlotBytes);
  return e.message();
}

void signPractice(PracticeRequest& request, const KeyPair& key) {
  request.signature = signMessage(signedBytes(request), key);
}

SignatureCheck verifyPractice(const PracticeRequest& request,
                              std::span<const std::uint8_t> public_key) {
  if (request.signature.empty()) return SignatureCheck::Unsigned;
  return verifyMessage(signedBytes(request), request.signature, public_key);
}

Check<> checkPracticeFields(const PracticeRequest& r, double half_length, double half_width) {
  if (r.balls.size() > kPracticeMaxBalls) {
    return Check<>::refuse("too_many_balls", "balls: at most " + std::to_string(kPracticeMaxBalls));
  }
  std::set<int> ids;
  for (const BallSpot& b : r.balls) {
    if (b.id < 0 || b.id > physics::kMaxBallId) {
      return Check<>::refuse("bad_ball_id",
                             "balls: an id must be 0-" + std::to_string(physics::kMaxBallId));
    }
    if (!ids.insert(b.id).second)
      return Check<>::refuse("ball_twice", "balls: ball " + std::to_string(b.id) + " twice");
    if (!std::isfinite(b.x) || !std::isfinite(b.y))
      return Check<>::refuse("non_finite", "balls: must be finite numbers");
    if (std::abs(b.x) > half_length || std::abs(b.y) > half_width) {
      return Check<>::refuse("ball_off_table",
                             "balls: ball " + std::to_string(b.id) + " is off the table");
    }
  }
  if (r.rack != 0 && !rules::gameOfNumber(r.rack)) {
    return Check<>::refuse("bad_rack",
                           "rack: must be a game's number (" + rackNumbers() + ") or 0 (clear)");
  }
  for (std::size_t i = 0; i < r.coefficients.size(); ++i) {
    if (!std::isfinite(r.coefficients[i])) {
      return Check<>::refuse("non_finite",
                             std::string(kPracticeCoefficients[i]) + ": must be a finite number");
    }
  }
  return Check<>::pass();
}

}  // namespace pool::protocol
