// Partition names from match ids, refusing what could be read as a pattern.
#include "net/match_partition.h"

#include <algorithm>

namespace pool::net {

namespace {

bool plainChar(char ch) {
  return (ch >= 'a' && ch <= 'z') || (ch >= 'A' && ch <= 'Z') || (ch >= '0' && ch <= '9') ||
         ch == '.' || ch == '_' || ch == '-';
}

}  // namespace

Result<std::string> matchPartition(std::string_view match) {
  if (match.empty()) return Result<std::string>::fail("no partition for an empty match id");
  if (match.size() > kMaxPartitionMatchId) {
    return Result<std::string>::fail("no partition for a match id of " +
                                     std::to_string(match.size()) + " bytes (at most " +
                                     std::to_string(kMaxPartitionMatchId) + ")");
  }
  if (!std::all_of(match.begin(), match.end(), plainChar)) {
    return Result<std::string>::fail(
        "no partition for a match id with a character other than letters, digits, '.', '_', "
        "'-'");
  }
  return Result<std::string>::ok(std::string(kMatchPartitionPrefix) + std::string(match));
}

}  // namespace pool::net
