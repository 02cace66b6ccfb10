// When the shooter's screen sends its live aim: at most `max_rate` a second while the cue moves,
// a keep-alive while it rests, the stroke at once. Pure: time passes only through `now`.
#pragma once

#include <optional>

#include "protocol/aim_sample.h"

namespace pool::client {

struct AimPace {
  double max_rate = 30.0;    ///< aims a second at most while the cue moves (20–60 keeps it live)
  double keep_alive = 0.25;  ///< s between aims while the cue rests (viewers hide it after 1 s)
};

class AimPacer {
 public:
  explicit AimPacer(AimPace pace = {}) : pace_(pace) {}

  /// True when `aim` (its cue values and turn; match, seat and numbers aside) should go out at
  /// `now` (s): a stroke or a new turn at once, a changed cue once 1/max_rate s passed since the
  /// last one sent, an unchanged one after keep_alive. Remembers it as sent when true.
  bool due(const protocol::AimSample& aim, double now);
  /// Aiming stopped (the shot went, the turn passed): the next aim goes out at once.
  void reset() { last_.reset(); }

 private:
  AimPace pace_;
  std::optional<protocol::AimSample> last_;
  double sent_at_ = 0.0;
};

}  // namespace pool::client
