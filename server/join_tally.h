// Counts what spectators and refused join requests do and says so once per period, so that a
// flood of them costs one log line a second instead of one each.
#pragma once

#include <cstdint>
#include <map>
#include <optional>
#include <string>

namespace pool::server {

/// Join events counted since the last summary, by what happened ("spectate accepted",
/// "seat bad_signature", "gone", ...).
class JoinTally {
 public:
  explicit JoinTally(double period = 1.0) : period_(period) {}

  /// Counts one `what` at `now` (s, monotonic).
  void add(const std::string& what, double now);

  /// Once `period` s have passed since the first event counted: "joins and leaves in T s: what
  /// n, ... (W watching, C clients tracked)", and the counts start over. Empty otherwise.
  std::optional<std::string> summary(double now, std::size_t watching, std::size_t tracked);
  /// Whether summary() would give a line at `now`.
  bool due(double now) const { return since_ && now - *since_ >= period_; }

  /// Every event counted since the tally was made.
  std::uint64_t total() const { return total_; }

 private:
  double period_;
  std::optional<double> since_;  ///< when the first event of this period was counted
  std::map<std::string, std::uint64_t> counts_;
  std::uint64_t total_ = 0;
};

}  // namespace pool::server
