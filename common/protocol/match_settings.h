// How a table is played, as whoever opens it chooses: the game, the race, who breaks, the shot
// clock, the points of a game of three-cushion.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "core/check.h"
#include "rules/game_rules.h"

namespace pool::protocol {

/// Who breaks the next rack of a race: the players in turn, or the winner of the last rack.
enum class BreakOrder : std::uint8_t { Alternate, Winner };

const char* toString(BreakOrder order);  ///< "alternate", "winner"
std::optional<BreakOrder> breakOrderOf(std::string_view name);

inline constexpr int kMaxRace = 15;                ///< racks to win, at most
inline constexpr int kMaxPoints = 100;             ///< three-cushion: points to win, at most
inline constexpr int kDefaultPoints = 5;           ///< three-cushion: two bots finish in minutes
inline constexpr double kMinShotClock = 5.0;       ///< s per shot, at least (when on)
inline constexpr double kMaxShotClock = 600.0;     ///< s per shot, at most
inline constexpr double kShotClockWarning = 10.0;  ///< s left when the warning starts (at most)

/// A match's settings. The shot clock (WPA style): `shot_clock` s for each shot, a warning when
/// little is left, and once per rack each player's first expiry is an extension of the same time
/// instead of a foul.
struct MatchSettings {
  rules::Game game = rules::Game::EightBall;
  int race_to = 1;              ///< racks to win the match, 1..kMaxRace (three-cushion: games)
  int points = kDefaultPoints;  ///< three-cushion: points that win a game, 1..kMaxPoints (other
                                ///< games: kDefaultPoints, unused)
  BreakOrder breaks = BreakOrder::Alternate;
  double shot_clock = 0.0;  ///< s per shot; 0: no clock; else kMinShotClock..kMaxShotClock
  /// A practice table: its players shoot as they like, ball in hand anywhere, and may lay out,
  /// re-rack and undo (protocol/practice_request.h); `game` is the rack it starts with and puts
  /// it on that game's table (any game: a pool table re-racks 8-, 9- or 10-ball, snooker's and
  /// three-cushion's their own game), and it has no race and no shot clock.
  bool practice = false;

  bool clockOn() const { return shot_clock > 0.0; }
  /// s left on the clock from which the warning shows: a third of the time, at most 10 s.
  double warningAt() const;
  bool operator==(const MatchSettings&) const = default;
};

/// Passes valid settings; refuses others with the setting and why ("race: must be 1 to 15 racks").
Check<> checkSettings(const MatchSettings& settings);

/// One line, e.g. "9-ball, race to 3, winner breaks, shot clock 35 s".
std::string describe(const MatchSettings& settings);

}  // namespace pool::protocol
