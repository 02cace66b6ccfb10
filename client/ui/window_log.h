// The window's JSON lines on stdout (with --json): shots sent, notes, states and motions.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "client/app/match_session.h"

namespace pool::ui {

/// Prints {"event": "shot", ...}: the shot `request` sent for `seat` of `match` as number `seq`.
void printShotLine(const std::string& match, int seat, std::uint32_t seq,
                   const protocol::ShotRequest& request);

/// Prints {"event": "note", "text", "problem"}.
void printNoteLine(const app::SessionNote& note);

/// Prints {"event": "hud", "texts": [...]}: every text the HUD drew in a frame.
void printHudLine(const std::vector<std::string>& texts);

/// Prints a line for each new state of the match followed and each shot whose motion starts.
class ProgressLog {
 public:
  /// Prints what is new in `session` since the last call.
  void report(const app::MatchSession& session);

 private:
  std::optional<std::uint32_t> last_revision_;
  std::optional<std::uint32_t> last_motion_;
};

}  // namespace pool::ui
