// The server's checks on the shooters' live aim before it relays it: only the seat whose turn it
// is, with its holding's token, in order, at a bounded rate, signed by the seat's key. Pure logic:
// time comes in as `now`.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "protocol/aim_sample.h"

namespace pool::server {

/// What the gate needs to know of the match an aim names, as it stands now.
struct AimTurn {
  bool aiming = false;  ///< a rack in play, no shot in motion, the match not closed
  int shooter = -1;     ///< the seat whose turn it is
  std::uint32_t shot_number = 0;
  std::uint64_t token = 0;               ///< the shooter's holding
  std::vector<std::uint8_t> public_key;  ///< the shooter's bound key
  bool banned = false;                   ///< that key is banned by the operator
};

/// Why an aim was not relayed, in the order the checks run (the signature, the one costly check,
/// last).
enum class AimDrop : std::uint8_t {
  None,          ///< relayed
  Malformed,     ///< unreadable, or values no cue can have (protocol::checkAim)
  NoSuchMatch,   ///< no open match of that id
  NotAiming,     ///< no rack in play, or a shot in motion
  NotShooter,    ///< not the seat whose turn it is (the other seat, or banned)
  BadToken,      ///< not the shooter's holding
  OtherTurn,     ///< its shot number is not the match's (an earlier turn's sample)
  Stale,         ///< its seq is not above the last one relayed for this turn (a replay)
  Flood,         ///< more than the rate allows from that seat this second
  BadSignature,  ///< unsigned, or not the seat key's signature
  Count
};

const char* toString(AimDrop drop);

/// How many aims a seat may have checked per second (the sender sends at most 60).
struct AimRates {
  int per_second = 90;
};

class AimGate {
 public:
  explicit AimGate(AimRates rates = {}) : rates_(rates) {}

  /// Checks `aim` against `turn` (null: no such match) at `now` (s); None when it may be relayed.
  /// A sample past the cheap checks counts toward its seat's rate whatever the signature says, so
  /// a flood costs at most `per_second` signature checks a second per seat.
  AimDrop check(const protocol::AimSample& aim, const AimTurn* turn, double now);

  /// Forgets `match` (it closed).
  void forget(const std::string& match);

  /// Aims dropped so far, by reason (index: AimDrop), and relayed.
  std::uint64_t dropped(AimDrop why) const { return dropped_[static_cast<std::size_t>(why)]; }
  std::uint64_t relayed() const { return dropped_[0]; }
  /// Aims dropped so far, whatever the reason.
  std::uint64_t droppedInAll() const {
    std::uint64_t n = 0;
    for (std::size_t i = 1; i < static_cast<std::size_t>(AimDrop::Count); ++i) n += dropped_[i];
    return n;
  }

 private:
  struct SeatTrack {
    std::uint64_t token = 0;
    std::uint32_t shot_number = 0;
    std::uint32_t last_seq = 0;
    double window_start = -1.0;
    int in_window = 0;
  };
  AimDrop count(AimDrop why) {
    ++dropped_[static_cast<std::size_t>(why)];
    return why;
  }

  AimRates rates_;
  std::map<std::pair<std::string, int>, SeatTrack> seats_;
  std::uint64_t dropped_[static_cast<std::size_t>(AimDrop::Count)] = {};
};

}  // namespace pool::server
