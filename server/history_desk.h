// The server's answers to history requests (replays): each request checked (readable, signed,
// within its bounds and its asker's share), then the stored strokes it asks for, as they were
// stored.
#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "net/server_transport.h"
#include "server/match/join_rate_limit.h"
#include "server/store/match_store.h"

namespace pool::server {

/// Counts of what the desk did with the requests it read.
struct HistoryCounts {
  std::uint64_t answered = 0;  ///< requests answered (found or not)
  std::uint64_t refused = 0;   ///< unreadable, unsigned, badly signed or out of bounds: no answer
  std::uint64_t limited = 0;   ///< over the participant's or the key's share: no answer
};

/// Reads requests from the store; never changes it. Time is passed in (s, monotonic).
class HistoryDesk {
 public:
  HistoryDesk(store::MatchStore& store, std::string server_id)
      : store_(store), server_(std::move(server_id)) {}

  /// The shots that answer `in` (at most its count; one shot saying why when none is found), or
  /// nothing for a request that is refused or over a share (counted, and said in `why` when
  /// given). A request's share: kPerSecond a second (kBurst at once) per DDS participant and per
  /// key, so neither many keys from one participant nor one key from many participants make the
  /// server read more than that; and all of them together kServerPerSecond (kServerBurst), since
  /// participants cost nothing.
  std::vector<protocol::HistoryShot> answer(const net::IncomingHistory& in, double now,
                                            std::string* why = nullptr);

  /// Says which stroke is still being played out (`match`, its number): such a stroke is stored
  /// before its frames and result go out, and is not answered until they have (a replay must not
  /// tell the result before the table does).
  void inMotion(std::function<bool(const std::string& match, std::uint32_t shot)> test) {
    in_motion_ = std::move(test);
  }

  const HistoryCounts& counts() const { return counts_; }

  static constexpr double kPerSecond = 4.0;
  static constexpr double kBurst = 8.0;
  static constexpr double kServerPerSecond = 32.0;
  static constexpr double kServerBurst = 64.0;

 private:
  store::MatchStore& store_;
  std::string server_;
  JoinRateLimit by_sender_{kPerSecond, kBurst};
  JoinRateLimit by_key_{kPerSecond, kBurst};
  /// Every participant's and key's together: the most the server reads for replays.
  JoinRateLimit all_{kServerPerSecond, kServerBurst};
  HistoryCounts counts_;
  std::function<bool(const std::string&, std::uint32_t)> in_motion_;
};

}  // namespace pool::server
