// The signed form of a shot command: one canonical, versioned, fixed-layout encoding of every
// field that matters, signed by the seat's player with Ed25519 and checked by the server.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "net/key_pair.h"
#include "net/shot_request.h"

namespace pool::net {

/// The version of the layout below; raised whenever it changes.
inline constexpr std::uint32_t kSignedLayoutVersion = 1;

/// Bytes of the encoding (fixed whatever the command holds).
inline constexpr std::size_t kSignedCommandBytes = 171;

/// The bytes a command's signature covers, all integers little-endian, doubles as their IEEE-754
/// bits:
///   "POOL-SHOT" (9) | layout version u32 | protocol version u32 |
///   match length u8, match bytes zero-padded to 40 | seat i32 | seat token u64 | seq u32 |
///   yaw, tip_side, tip_height, elevation, speed f64 | speed_is_ball u8 |
///   called ball i32 (-1: none) | pocket length u8, pocket bytes zero-padded to 32 | safety u8 |
///   placement u8, cue_ball_x, cue_ball_y f64 (0 without placement) | option u8.
/// The token is covered so that a command signed for one holding of a seat cannot be replayed
/// into a later holding of it; the signature itself is not.
using SignedBytes = std::array<std::uint8_t, kSignedCommandBytes>;
SignedBytes signedBytes(const ShotRequest& command);

/// Fills in `command.signature` (64 bytes) with `key`'s signature of signedBytes(command).
void signCommand(ShotRequest& command, const KeyPair& key);

/// How a command's signature fares against a seat's public key.
enum class SignatureCheck : std::uint8_t {
  Valid,
  Unsigned,      ///< no signature at all
  BadSignature,  ///< not 64 bytes, or not the key's signature of these fields
};

/// Checks `command`'s signature against `public_key` (32 bytes; any other length fails).
SignatureCheck verifyCommand(const ShotRequest& command, std::span<const std::uint8_t> public_key);

}  // namespace pool::net
