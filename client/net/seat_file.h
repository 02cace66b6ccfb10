// A player's identity on disk: the seat it holds (match, seat, token) and the last sequence
// number it used, so a restarted bot or window can rejoin with its token; its
// signing key is kept beside it (protocol/key_pair.h).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>

#include "core/result.h"

namespace pool::client {

/// What a player remembers of its seat.
struct SeatRecord {
  std::string match;
  int seat = -1;
  std::uint64_t token = 0;
  std::uint32_t last_seq = 0;  ///< the last sequence number sent
};

/// Whether a player who asks to play `wanted` (empty: the first free seat; "new": a table of
/// their own; else a match id) takes back the seat they kept: only when they asked for no other
/// table (a practice table asked for with a finished match's seat kept took that seat back).
bool takesBackKeptSeat(const SeatRecord& kept, const std::string& wanted);

/// Reads a seat file (JSON: {"match", "seat", "token", "last_seq"}). Empty when the file does
/// not exist; a failure when it exists but cannot be read.
Result<std::optional<SeatRecord>> readSeatFile(const std::filesystem::path& path);

/// Where the key pair that signs the seat's commands is kept: `<seat file>.key`.
std::filesystem::path keyFileFor(const std::filesystem::path& seat_file);

/// Writes it atomically (a temporary file renamed over it). Empty string on success, else why.
std::string writeSeatFile(const std::filesystem::path& path, const SeatRecord& record);

}  // namespace pool::client
