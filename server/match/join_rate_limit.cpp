// The per-client (or per-participant) token buckets of join requests.
#include "server/match/join_rate_limit.h"

#include <algorithm>

namespace pool::server {

bool JoinRateLimit::allow(const std::string& client, double now) {
  if (now - swept_ >= 1.0) sweep(now);
  auto [it, fresh] = buckets_.try_emplace(client, Bucket{burst_, now});
  Bucket& b = it->second;
  if (!fresh) {
    b.tokens = std::min(burst_, b.tokens + std::max(0.0, now - b.at) * per_second_);
    b.at = now;
  }
  if (b.tokens < 1.0) return false;
  b.tokens -= 1.0;
  return true;
}

bool JoinRateLimit::tellRefusal(const std::string& client, double now) {
  const auto it = buckets_.find(client);
  if (it == buckets_.end() || now - it->second.told < 1.0) return false;
  it->second.told = now;
  return true;
}

void JoinRateLimit::sweep(double now) {
  swept_ = now;
  std::erase_if(buckets_, [&](const auto& entry) {
    const Bucket& b = entry.second;
    return b.tokens + (now - b.at) * per_second_ >= burst_;
  });
}

}  // namespace pool::server
