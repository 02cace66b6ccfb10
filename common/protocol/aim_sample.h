// The shooter's cue while aiming (heading, tip, elevation, draw-back, the stroke): the sample a
// seated shooter signs in the envelope with tag Aim, and the one the server relays to viewers.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/check.h"
#include "protocol/command_limits.h"
#include "protocol/envelope.h"
#include "protocol/key_pair.h"

namespace pool::protocol {

/// One look at the shooter's cue. Cosmetic: nothing in it ever reaches the shot the server plays.
/// Angles in radians, tip offsets in fractions of R, positions in m (table frame).
struct AimSample {
  std::string match;
  int seat = 0;                   ///< the shooter's seat, 0 or 1
  std::uint64_t seat_token = 0;   ///< the holding it is sent for (not relayed)
  std::uint32_t seq = 0;          ///< the shooter's aim number within this turn, from 1
  std::uint32_t shot_number = 0;  ///< the match's shots so far (MatchState.shot_number)
  double yaw = 0.0;               ///< cue heading in the table plane
  double tip_side = 0.0;
  double tip_height = 0.0;
  double elevation = 0.0;
  double power = 0.0;       ///< 0–1: how far the cue is drawn back
  bool stroke = false;      ///< released: the cue strokes through from `power`
  double cue_ball_x = 0.0;  ///< where the cue ball is (in hand: where it is held)
  double cue_ball_y = 0.0;
  std::vector<std::uint8_t> signature;  ///< the seat key's (player's sample) or empty (relayed)
};

/// Bytes of an aim sample's signed encoding (fixed).
inline constexpr std::size_t kSignedAimBytes = kEnvelopeHeaderBytes + 4 + 5 * 8 + 1 + 2 * 8;

/// The bytes the shooter signs: the envelope header (tag Aim, match, seat, seat token, seq), then
/// shot_number u32 | yaw, tip_side, tip_height, elevation, power f64 | stroke u8 | cue_ball_x,
/// cue_ball_y f64.
std::vector<std::uint8_t> signedBytes(const AimSample& aim);

/// Fills in `aim.signature` with `key`'s signature of signedBytes(aim).
void signAim(AimSample& aim, const KeyPair& key);

/// Checks `aim`'s signature against `public_key`.
SignatureCheck verifyAim(const AimSample& aim, std::span<const std::uint8_t> public_key);

/// Refuses `aim`'s values where they cannot be a cue on this table ("<field>: <reason>"): the
/// match id non-empty, the seat 0 or 1, every number finite, the cue's angles and tip within
/// physics::checkShotRange's ranges, power in [0, 1], the cue ball on the playing surface.
Check<> checkAim(const AimSample& aim, const CommandLimits& limits);

}  // namespace pool::protocol
