// The aim sample's signed encoding, its Ed25519 signature and the range check of its values.
#include "protocol/aim_sample.h"

#include <cassert>
#include <cmath>

namespace pool::protocol {

std::vector<std::uint8_t> signedBytes(const AimSample& a) {
  SignedEncoder e({MessageTag::Aim, a.match, a.seat, a.seat_token, a.seq});
  e.u32(a.shot_number);
  e.f64(a.yaw);
  e.f64(a.tip_side);
  e.f64(a.tip_height);
  e.f64(a.elevation);
  e.f64(a.power);
  e.u8(static_cast<std::uint8_t>(a.stroke));
  e.f64(a.cue_ball_x);
  e.f64(a.cue_ball_y);
  assert(e.message().size() == kSignedAimBytes);
  return e.message();
}

void signAim(AimSample& aim, const KeyPair& key) {
  aim.signature = signMessage(signedBytes(aim), key);
}

SignatureCheck verifyAim(const AimSample& aim, std::span<const std::uint8_t> public_key) {
  if (aim.signature.empty()) return SignatureCheck::Unsigned;
  return verifyMessage(signedBytes(aim), aim.signature, public_key);
}

Check<> checkAim(const AimSample& a, const CommandLimits& limits) {
  auto refuse = [](const char* code, std::string sentence) {
    return Check<>::refuse(code, std::move(sentence));
  };
  if (a.match.empty()) return refuse("bad_match_id", "match: empty");
  if (a.seat != 0 && a.seat != 1) return refuse("bad_seat", "seat: not 0 or 1");
  for (const double v :
       {a.yaw, a.tip_side, a.tip_height, a.elevation, a.power, a.cue_ball_x, a.cue_ball_y}) {
    if (!std::isfinite(v)) return refuse("non_finite", "values: not finite");
  }
  // An aim has no speed yet: its power is checked on its own.
  auto cue =
      physics::checkShotRange({0.0, a.elevation, a.tip_side, a.tip_height, a.yaw}, limits, false);
  if (!cue) return refuse(physics::toString(cue.code()), cue.error());
  if (a.power < 0.0 || a.power > 1.0) return refuse("power_out_of_range", "power: not in [0, 1]");
  if (std::abs(a.cue_ball_x) > limits.half_length || std::abs(a.cue_ball_y) > limits.half_width) {
    return refuse("placement_out_of_range", "cue ball: off the playing surface");
  }
  return Check<>::pass();
}

}  // namespace pool::protocol
