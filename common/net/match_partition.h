// The DDS partition a match's own samples travel in: one name per match, derived from its id.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

#include "core/result.h"

namespace pool::net {

/// Every match partition's name is this prefix and the match id; the lobby (MatchInfo) and the
/// join traffic stay in the default partition, where every client sees them.
inline constexpr std::string_view kMatchPartitionPrefix = "pool.match.";
/// The longest match id a partition is made for (a match id's wire field holds 39 bytes).
inline constexpr std::size_t kMaxPartitionMatchId = 39;

/// The partition of `match` ("pool.match.<id>"), or why the id cannot name one: empty, longer
/// than kMaxPartitionMatchId, or holding a character other than ASCII letters, digits, '.', '_'
/// and '-' (so no '*' or '?', which DDS reads as wildcards, ever reaches a partition name).
Result<std::string> matchPartition(std::string_view match);

}  // namespace pool::net
