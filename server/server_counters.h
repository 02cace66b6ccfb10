// What the server has done since it started, for the operator's status: requests accepted and
// refused, and how long the database's commits took.
#pragma once

#include <algorithm>
#include <cstdint>

namespace pool::server {

/// Counted by the server's loop; read by the admin desk.
struct ServerCounters {
  std::uint64_t commands_accepted = 0;
  std::uint64_t commands_refused = 0;
  std::uint64_t joins_accepted = 0;
  std::uint64_t joins_refused = 0;
  std::uint64_t admin_requests = 0;  ///< every request read on the admin socket
  std::uint64_t admin_refused = 0;   ///< those answered with an error
  std::uint64_t commits = 0;         ///< transactions written to the database
  double commit_ms_total = 0.0;
  double commit_ms_max = 0.0;
  double commit_ms_last = 0.0;

  /// Counts one commit that took `ms`.
  void commit(double ms) {
    ++commits;
    commit_ms_total += ms;
    commit_ms_last = ms;
    commit_ms_max = std::max(commit_ms_max, ms);
  }
  double commitMsMean() const {
    return commits ? commit_ms_total / static_cast<double>(commits) : 0.0;
  }
};

}  // namespace pool::server
