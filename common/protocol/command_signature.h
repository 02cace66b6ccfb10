// The signed form of a shot command: the envelope (protocol/envelope.h) with tag Shot, then every
// field that matters, signed by the seat's player with Ed25519 and checked by the server.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "protocol/envelope.h"
#include "protocol/key_pair.h"
#include "protocol/shot_request.h"

namespace pool::protocol {

/// Bytes of a shot command's encoding (fixed whatever the command holds).
inline constexpr std::size_t kSignedCommandBytes =
    kEnvelopeHeaderBytes + 5 * 8 + 1 + 4 + 33 + 1 + 1 + 2 * 8 + 1;

/// The bytes a command's signature covers: the envelope header (tag Shot, match, seat, seat
/// token, seq), then yaw, tip_side, tip_height, elevation, speed f64 | speed_is_ball u8 |
/// called ball i32 (-1: none) | pocket length u8 + 32 | safety u8 | placement u8, cue_ball_x,
/// cue_ball_y f64 (0 without placement) | option u8. The token is covered so that a command
/// signed for one holding of a seat cannot be replayed into a later holding of it.
std::vector<std::uint8_t> signedBytes(const ShotRequest& command);

/// Fills in `command.signature` (64 bytes) with `key`'s signature of signedBytes(command).
void signCommand(ShotRequest& command, const KeyPair& key);

/// Checks `command`'s signature against `public_key` (32 bytes; any other length fails).
SignatureCheck verifyCommand(const ShotRequest& command, std::span<const std::uint8_t> public_key);

}  // namespace pool::protocol
