// The canonical encoding of a shot command inside the signed envelope, and its Ed25519 signature.
#include "protocol/command_signature.h"

#include <cassert>

namespace pool::protocol {

namespace {

constexpr std::size_t kPocketField = 32;

}  // namespace

std::vector<std::uint8_t> signedBytes(const ShotRequest& c) {
  SignedEncoder e({MessageTag::Shot, c.match, c.seat, c.seat_token, c.seq});
  e.f64(c.cue.yaw);
  e.f64(c.cue.tip_side);
  e.f64(c.cue.tip_height);
  e.f64(c.cue.elevation);
  e.f64(c.cue.speed);
  e.u8(static_cast<std::uint8_t>(c.cue.speed_is_ball));
  e.i32(static_cast<std::int32_t>(c.called_ball.value_or(-1)));
  e.text(c.called_pocket, kPocketField);
  e.u8(static_cast<std::uint8_t>(c.safety));
  e.u8(static_cast<std::uint8_t>(c.cue_ball_at.has_value()));
  e.f64(c.cue_ball_at ? c.cue_ball_at->x() : 0.0);
  e.f64(c.cue_ball_at ? c.cue_ball_at->y() : 0.0);
  e.u8(static_cast<std::uint8_t>(c.option));
  assert(e.message().size() == kSignedCommandBytes);
  return e.message();
}

void signCommand(ShotRequest& command, const KeyPair& key) {
  command.signature = signMessage(signedBytes(command), key);
}

SignatureCheck verifyCommand(const ShotRequest& command, std::span<const std::uint8_t> public_key) {
  if (command.signature.empty()) return SignatureCheck::Unsigned;
  return verifyMessage(signedBytes(command), command.signature, public_key);
}

}  // namespace pool::protocol
