// The per-period count of spectators' joins and leaves and of refused joins.
#include "server/join_tally.h"

#include <cstdio>

namespace pool::server {

void JoinTally::add(const std::string& what, double now) {
  if (!since_) since_ = now;
  ++counts_[what];
  ++total_;
}

std::optional<std::string> JoinTally::summary(double now, std::size_t watching,
                                              std::size_t tracked) {
  if (!due(now)) return std::nullopt;
  std::string what;
  for (const auto& [name, n] : counts_) {
    what += (what.empty() ? "" : ", ") + name + " " + std::to_string(n);
  }
  char head[64];
  std::snprintf(head, sizeof head, "joins and leaves in %.1f s: ", now - *since_);
  char tail[96];
  std::snprintf(tail, sizeof tail, " (%zu watching, %zu clients tracked)", watching, tracked);
  counts_.clear();
  since_.reset();
  return head + what + tail;
}

}  // namespace pool::server
