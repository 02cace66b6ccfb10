// Named QoS profiles, one per topic of docs/PROTOCOL.md, applied alike to its writers and readers.
#pragma once

#include <chrono>
#include <cstdint>
#include <optional>

namespace pool::net {

enum class Reliability : std::uint8_t { BestEffort, Reliable };
enum class Durability : std::uint8_t { Volatile, TransientLocal };

/// The QoS a topic's writers and readers share. Readers ignore `liveliness_lease` (they accept any
/// lease a writer offers) and `max_blocking`.
struct QosProfile {
  Reliability reliability = Reliability::Reliable;
  Durability durability = Durability::Volatile;
  std::uint32_t history_depth = 1;  ///< keep-last depth per instance; 0 = keep all
  /// Automatic liveliness with this lease on writers: a writer whose process stops is reported
  /// not alive to readers once the lease runs out. Empty: DDS's default (infinite).
  std::optional<std::chrono::nanoseconds> liveliness_lease;
  /// Whether a writer that unregisters an instance (or is deleted, or loses liveliness) also
  /// disposes it. DDS's default is true; readers then see Disposed instead of NoWriters.
  bool autodispose = true;
  /// How long a reliable write may block on a full queue before it fails with a timeout.
  std::chrono::nanoseconds max_blocking = std::chrono::seconds(1);

  bool keepAll() const { return history_depth == 0; }
};

namespace qos {

/// Lease for player writers (JoinRequest, ShotCommand) unless the caller chooses another.
inline constexpr std::chrono::milliseconds kPlayerLease{5000};

/// MatchInfo: reliable, transient-local, keep-last 1 (a late joiner sees every open match).
QosProfile lobby();
/// JoinRequest: reliable, volatile, keep-all (a leave right after a join is not overwritten);
/// a player writer: automatic liveliness with `lease`, no autodispose (a vanished player's
/// instances read as NoWriters, not Disposed).
QosProfile joinRequest(std::chrono::nanoseconds lease = kPlayerLease);
/// JoinReply: reliable, transient-local, keep-last 1 per client (a reply written before the
/// client's reader matched still reaches it).
QosProfile joinReply();
/// ShotCommand: reliable, volatile, keep-all; a player writer like joinRequest's.
QosProfile command(std::chrono::nanoseconds lease = kPlayerLease);
/// ShotResult: reliable, transient-local, keep-last 1 per match and seat.
QosProfile result();
/// ShotResult answering a command that names no match or seat of the server's (in the default
/// partition): reliable, volatile, keep-last 1. Nobody joins late for a refusal, and a writer
/// that kept one would hold a stranger's every invented key.
QosProfile strayResult();
/// TableSnapshot: best-effort, volatile, keep-last 1 (a lost frame is replaced by the next one).
QosProfile snapshot();
/// MatchState: reliable, transient-local, keep-last 1 (a late joiner gets the latest at once).
QosProfile state();
/// AimCommand and CueAim: best-effort, volatile, keep-last 1 (cosmetic: only the latest aim
/// matters, and a lost one is replaced by the next).
QosProfile aim();
/// The server's reader of AimCommand: as aim() but keep-last 64. The topic has no key, so every
/// seat's aims (and a stranger's) share one history, which the server takes every loop.
QosProfile aimReader();
/// HistoryShot, both ends: reliable, volatile, keep-last 32 (the answers to a burst of requests;
/// a reader that was not there when one was written has no use for it).
QosProfile history();

}  // namespace qos
}  // namespace pool::net
