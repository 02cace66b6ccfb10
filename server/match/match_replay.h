// A stored match played again on a fresh match: same rack seed, its commands fed one at a time.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "protocol/key_pair.h"
#include "protocol/seat_request.h"
#include "server/match/match.h"
#include "server/match/match_snapshot.h"
#include "server/match/shot_record.h"

namespace pool::server {

/// Feeds a stored match's accepted commands to `target` (a fresh match opened with the stored rack
/// seed), each once the table is at rest and `pause` s have passed, and checks every re-simulated
/// shot against the stored one: the table at the strike and the event log must be identical.
class MatchReplay {
 public:
  /// Seats the stored players in `target` with `tokens` and fresh key pairs (the replay's own; the
  /// stored tokens stay private to the stored match): each stored command is signed again for
  /// `target`, as its seat's client would sign it.
  MatchReplay(const MatchSnapshot& stored, std::vector<ShotRecord> commands, Match& target,
              std::array<std::uint64_t, 2> tokens, double pause);

  /// At `now`: feeds the next command when it is due. The answer to publish, or empty.
  std::optional<CommandAnswer> step(double now);

  const std::string& matchId() const { return target_.id(); }
  bool done() const { return next_ >= commands_.size() && !target_.inMotion(); }
  /// Commands fed and accepted so far, and those whose shot differed from the stored one.
  std::uint32_t replayed() const { return replayed_; }
  const std::vector<std::string>& differences() const { return differences_; }

 private:
  protocol::SeatRequest signedRematch(int seat);
  void check(const ShotRecord& stored, const CommandAnswer& answer);

  std::vector<ShotRecord> commands_;
  Match& target_;
  std::array<std::uint64_t, 2> tokens_;
  std::array<protocol::KeyPair, 2> keys_;
  std::array<std::uint32_t, 2> seqs_{};  ///< the replay's own sequence numbers per seat
  double pause_;
  std::size_t next_ = 0;
  std::optional<double> idle_since_;
  std::uint32_t replayed_ = 0;
  std::vector<std::string> differences_;
};

}  // namespace pool::server
