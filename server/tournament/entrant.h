// An entrant of a tournament (id, display name, rating, bot or person) and the checks on a field.
#pragma once

#include "core/check.h"

#include <cstddef>
#include <string>
#include <vector>

namespace pool::tournament {

/// Who plays. Entrants are named by their index in the field as given (the entry order).
struct Entrant {
  std::string id = {};    ///< unique in the field: a player's hex public key, say
  std::string name = {};  ///< what people see; not empty
  double rating = 0.0;    ///< seeds the field: highest first
  bool bot = false;       ///< a bot rather than a person
};

inline constexpr int kMinEntrants = 3;
inline constexpr int kMaxEntrants = 32;
/// The longest id or name, in bytes.
inline constexpr std::size_t kMaxTextBytes = 256;

/// Passes a field of kMinEntrants to kMaxEntrants entrants with distinct ids, names that are not
/// empty (both clean UTF-8 of at most kMaxTextBytes: no control characters) and finite ratings;
/// refuses with code "bad_entrants" and the first fault otherwise.
Check<> checkEntrants(const std::vector<Entrant>& entrants);

}  // namespace pool::tournament
