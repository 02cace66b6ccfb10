// The per-period count of refused shot commands.
#include "server/rejection_tally.h"

#include <cstdio>

namespace pool::server {

void RejectionTally::add(protocol::RejectReason reason, double now) {
  const auto index = static_cast<std::size_t>(reason);
  if (index >= kReasons) return;
  if (!since_) since_ = now;
  ++counts_[index];
  ++total_;
}

std::optional<std::string> RejectionTally::summary(double now) {
  if (!since_ || now - *since_ < period_) return std::nullopt;
  std::uint64_t n = 0;
  std::string reasons;
  for (std::size_t i = 0; i < kReasons; ++i) {
    if (counts_[i] == 0) continue;
    n += counts_[i];
    reasons += (reasons.empty() ? "" : ", ") +
               std::string(protocol::toString(static_cast<protocol::RejectReason>(i))) + " " +
               std::to_string(counts_[i]);
  }
  char head[96];
  std::snprintf(head, sizeof head,
                "refused %llu shot commands in %.1f s: ", static_cast<unsigned long long>(n),
                now - *since_);
  counts_.fill(0);
  since_.reset();
  return head + reasons;
}

}  // namespace pool::server
