// An operator's request to a running server, checked field by field before anything acts on it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"

namespace pool::admin {

/// What the operator asks for.
enum class Verb {
  Status,
  List,
  Close,
  Ban,
  Unban,
  Bans,
  Backup,
  TournamentCreate,
  TournamentStart,
  TournamentCancel,
  Tournaments,
};

/// A checked request: only the fields its verb uses are set.
struct AdminRequest {
  Verb verb = Verb::Status;
  std::string match = {};              ///< close: the match id
  std::vector<std::uint8_t> key = {};  ///< ban, unban: a 32-byte Ed25519 public key
  std::string reason = {};             ///< close, ban: shown to the players concerned
  std::string path = {};               ///< backup: an absolute path for the copy
  std::string tournament = {};         ///< tournament-start, -cancel: the tournament id
  std::string name = {};    ///< tournament-create: its name, like a player name (1-31 bytes)
  std::string format = {};  ///< tournament-create: "single", "double" or "round-robin"
  int game = 0;             ///< tournament-create: the game's number (8, 9, 10, 3, 22)
  int race = 0;             ///< tournament-create: each match a race to this many racks (1-15)
  int entrants = 0;         ///< tournament-create: the entrants it takes (3-32)
  bool handicap = false;    ///< tournament-create (optional): racks on the wire by rating
};

/// The longest request line the server reads (bytes, newline excluded).
inline constexpr std::size_t kMaxRequestBytes = 8192;

/// The verb's name ("status", "list", ...).
const char* toString(Verb verb);

/// Reads one request line: a JSON object {"verb": ..., and the verb's fields}. Every field is
/// checked (a match or tournament id of 1-39 printable bytes, a key of 64 hex digits, a reason of
/// 1-120 bytes of UTF-8 without control characters, an absolute path without control characters;
/// a tournament's name of 1-31 bytes of UTF-8 without control characters, its format, game, race
/// of 1-15 and 3-32 entrants); unknown verbs and unknown or missing fields are refused. The
/// reason is one line.
Result<AdminRequest> parseRequest(const std::string& line);

/// The request as the line parseRequest reads.
std::string requestLine(const AdminRequest& request);

}  // namespace pool::admin
