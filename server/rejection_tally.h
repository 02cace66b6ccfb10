// Counts refused shot commands by reason and says so once per period, so that a flood of bad
// commands costs one log line a second instead of one per command.
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>

#include "protocol/protocol_enums.h"

namespace pool::server {

/// Refusals counted since the last summary.
class RejectionTally {
 public:
  explicit RejectionTally(double period = 1.0) : period_(period) {}

  /// Counts one refusal at `now` (s, monotonic).
  void add(protocol::RejectReason reason, double now);

  /// Once `period` s have passed since the first refusal counted: "refused N shot commands in
  /// T s: reason n, ..." (reasons in enum order), and the counts start over. Empty otherwise.
  std::optional<std::string> summary(double now);

  /// Every refusal counted since the tally was made.
  std::uint64_t total() const { return total_; }

 private:
  static constexpr std::size_t kReasons =
      static_cast<std::size_t>(protocol::RejectReason::BadPractice) + 1;

  double period_;
  std::optional<double> since_;  ///< when the first refusal of this period was counted
  std::array<std::uint64_t, kReasons> counts_{};
  std::uint64_t total_ = 0;
};

}  // namespace pool::server
