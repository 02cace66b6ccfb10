// Watching one match without a window: late join, then every state change, shot result and a
// count of each shot's frames, handed out as JSON lines.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "client/net/game_client.h"

namespace pool::client {

/// What to watch.
struct SpectatorConfig {
  std::string match = "any";   ///< a match id, or "any": the lowest-numbered match in play
  bool exit_when_over = true;  ///< done once the match is over (or closed)
  double join_retry = 1.0;     ///< s between spectate requests while unanswered
};

/// A headless spectator. Time is passed in (s on any monotonic clock).
class Spectator {
 public:
  using Emit = std::function<void(const std::string& line)>;

  Spectator(GameClient& client, SpectatorConfig config, Emit emit);

  /// Handles what arrived and emits lines for it.
  void step(double now);

  bool done() const { return done_; }
  /// The match being watched (empty until chosen).
  const std::string& match() const { return target_; }
  /// The watched table as last seen: the latest frame of a shot in motion, or the layout of the
  /// latest state, whichever came last. Null before either arrived.
  const std::vector<physics::Ball>* latestBalls() const {
    return latest_balls_ ? &*latest_balls_ : nullptr;
  }

 private:
  struct Frames {
    std::uint32_t count = 0;
    std::uint32_t first = 0;
    std::uint32_t last = 0;
  };

  void choose(double now);
  void handle(const ClientEvent& event);
  void emitState(const MatchView& view);
  void countFrame(const TableFrame& frame);
  void emitFrameCounts();

  GameClient& client_;
  SpectatorConfig config_;
  Emit emit_;
  std::string target_;
  std::optional<std::uint32_t> request_;
  bool watching_ = false;
  double sent_at_ = -1e9;
  std::optional<std::uint32_t> printed_revision_;
  std::optional<std::uint32_t> joined_at_shot_;  ///< shots played when the first state came
  std::map<std::uint32_t, Frames> frames_;       ///< by shot number
  std::vector<std::uint32_t> shots_done_;        ///< shots whose final result came this step
  std::optional<MatchView> ending_;              ///< the state that ended the match
  std::optional<double> ending_since_;           ///< when it was seen (s)
  std::uint32_t last_result_ = 0;                ///< the highest shot with a final result printed
  std::optional<std::vector<physics::Ball>> latest_balls_;
  bool done_ = false;
};

/// How long a spectator waits for the last shot's result after the match is over, s.
inline constexpr double kEndLinger = 1.0;

}  // namespace pool::client
