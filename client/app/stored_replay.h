// A stored shot of any match, asked of its server and played again on the caller's clock: the shot
// wanted (walked between 1 and the match's stored shots), the latest answer to our asks, its
// frames.
#pragma once

#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "client/app/shot_replay.h"
#include "protocol/history.h"

namespace pool::app {

/// The frame of `frames` (every 1/hz s from the strike, as app::replayFrames builds them) shown
/// `t` s after the strike: the last one at or before `t`; the first before the strike, the last
/// (the table at rest) from its time on. Null when there are no frames.
const ReplayFrame* frameAt(const std::vector<ReplayFrame>& frames, double t);

/// Shot `shot` moved by `step` and kept within 1..`shots` (1 when the match has none).
std::uint32_t steppedShot(std::uint32_t shot, int step, std::uint32_t shots);

/// "Replay of srv-1, shot 3 of 9: Ada - <the verdict in words>" (the shooter "Player N" when the
/// seat has no name; no verdict: the dash and what follows are left out).
std::string storedShotTitle(const protocol::HistoryShot& shot);

/// One stored shot of one match at a time, played back. Pure: the caller sends the asks it says
/// are due (ask), hands it the answers (take) and reads the balls at its own time (s, any steady
/// clock). The replay is open from open() to close().
class StoredReplay {
 public:
  /// The frames' rate, Hz.
  static constexpr double kHz = 60.0;
  /// How long the layout at the strike shows before the shot plays, s.
  static constexpr double kLead = 0.5;
  /// An ask not answered within this long is sent again, s.
  static constexpr double kAskAgain = 1.0;
  /// Asks sent for one shot before it is given up.
  static constexpr int kAsksPerShot = 6;

  /// Opens the replay of shot `shot` of `match`; 0: its last (`known_shots`, the lobby's count
  /// when known, is asked first; without it shot 1, which tells how many the match has).
  void open(std::string match, std::uint32_t shot = 0, std::uint32_t known_shots = 0);
  /// Closes it: nothing kept, nothing asked.
  void close();
  bool isOpen() const { return !match_.empty(); }
  const std::string& match() const { return match_; }

  /// The shot to ask for now (first ask, or again after kAskAgain s without its answer), if any;
  /// once kAsksPerShot asks went unanswered, problem() says so and nothing more is asked.
  std::optional<std::uint32_t> due(double now);
  /// The ask just sent as request `request` at `now`.
  void asked(std::uint32_t request, double now);
  /// The ask could not be sent at `now`: `why` is the problem (tried again as an unanswered ask).
  void notAsked(const std::string& why, double now);
  /// An answer to one of our asks of the shot wanted (any other is ignored: false). Found, it is
  /// the shot shown from now on, played from its strike at `now`; not found, its error is the
  /// problem (when the last shot was wanted and the answer tells another, that one is asked).
  bool take(protocol::HistoryShot answer, double now);

  /// The shot before or after the one wanted (within 1..shots), asked for; false when there is
  /// none.
  bool previous();
  bool next();
  bool hasPrevious() const { return wanted_ > 1; }
  bool hasNext() const { return wanted_ < shots_; }
  /// Plays the shot shown again from its strike at `now`.
  void again(double now);

  /// The shot shown, once one arrived.
  const protocol::HistoryShot* shown() const { return shown_ ? &*shown_ : nullptr; }
  /// The shot wanted (0: the last, not yet known); the match's stored shots as last told (0: not
  /// yet).
  std::uint32_t wanted() const { return wanted_; }
  std::uint32_t shots() const { return shots_; }
  /// True while the shot wanted is asked and not yet shown.
  bool waiting() const { return isOpen() && (!shown_ || shown_->shot_number != wanted_); }
  /// Why nothing (or not the shot wanted) is shown, in one line; empty when all is well.
  const std::string& problem() const { return problem_; }

  /// The time of the shot shown at `now`, s since its strike (negative before it).
  double time(double now) const { return now - start_; }
  /// The balls of the shot shown at `now` (frameAt); none before a shot arrived.
  std::optional<std::vector<physics::Ball>> balls(double now) const;
  /// True once the shot shown has come to rest (its last frame shown).
  bool atRest(double now) const;

 private:
  void ask(std::uint32_t shot);

  std::string match_;
  std::uint32_t wanted_ = 0;
  std::uint32_t shots_ = 0;
  bool last_wanted_ = false;  ///< the match's last shot, whatever its number turns out to be
  std::set<std::uint32_t> requests_;  ///< our asks of the shot wanted
  std::optional<double> asked_at_;
  int asks_ = 0;  ///< sent for the shot wanted
  bool due_ = false;
  std::optional<protocol::HistoryShot> shown_;
  std::vector<ReplayFrame> frames_;
  double start_ = 0.0;  ///< the strike on the caller's clock
  std::string problem_;
};

}  // namespace pool::app
