// How often one client (or one DDS participant) may ask the server for a seat or to watch: a token
// bucket per key.
#pragma once

#include <cstddef>
#include <string>
#include <unordered_map>

namespace pool::server {

/// A client may send `burst` join requests at once and `per_second` a second after that; the
/// rest are refused unread. The key is a client id as one DDS participant sends it (anyone may
/// write under any id, so an id alone is no one's to charge), or a DDS participant alone for the
/// limit per participant. Only clients that asked within the last burst / per_second seconds are
/// tracked (a full bucket holds nothing worth keeping), so a flood from many client ids leaves
/// nothing behind once it stops. Time is passed in (s, monotonic).
class JoinRateLimit {
 public:
  explicit JoinRateLimit(double per_second = kPerSecond, double burst = kBurst)
      : per_second_(per_second), burst_(burst) {}

  /// Takes one request of `client` at `now` from its bucket; false when the bucket is empty.
  bool allow(const std::string& client, double now);
  /// Whether a refusal of `client`'s requests over its limit is to be sent at `now`: once a second
  /// at most (the others are dropped unanswered; a flood is told, not answered request by request).
  /// Call after allow() refused it.
  bool tellRefusal(const std::string& client, double now);
  /// `client` is gone: its bucket goes too.
  void forget(const std::string& client) { buckets_.erase(client); }
  /// Drops the buckets that have filled up again by `now` (allow() does so once a second; this is
  /// for the quiet after a flood, and before the buckets are counted).
  void sweep(double now);
  /// Clients tracked now.
  std::size_t tracked() const { return buckets_.size(); }

  static constexpr double kPerSecond = 10.0;
  static constexpr double kBurst = 20.0;

 private:
  struct Bucket {
    double tokens = 0.0;
    double at = 0.0;       ///< when `tokens` was last brought up to date
    double told = -1.0e9;  ///< when a refusal was last sent
  };

  double per_second_;
  double burst_;
  std::unordered_map<std::string, Bucket> buckets_;
  double swept_ = 0.0;
};

}  // namespace pool::server
