// A tournament as the server publishes it (TournamentInfo): its field, its bracket and where it
// stands, for the lobby, the window, the page and the bots that play in it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "rules/game_rules.h"

namespace pool::protocol {

enum class TournamentFormat : std::uint8_t { SingleElimination, DoubleElimination, RoundRobin };
enum class TournamentPhase : std::uint8_t { Entry, Running, Finished, Cancelled };

const char* toString(TournamentFormat format);  ///< "single", "double", "round-robin"
const char* toString(TournamentPhase phase);    ///< "entry", "running", "finished", "cancelled"

/// The most entrants a tournament takes, and matches its bracket holds (double elimination's
/// 2N - 1 with the reset).
inline constexpr std::size_t kMaxTournamentEntrants = 32;
inline constexpr std::size_t kMaxTournamentMatches = 64;
/// A round robin's entrants, at most: its N(N-1)/2 matches all within kMaxTournamentMatches.
inline constexpr int kMaxRoundRobinEntrants = 11;
static_assert(kMaxRoundRobinEntrants * (kMaxRoundRobinEntrants - 1) / 2 <= kMaxTournamentMatches &&
              (kMaxRoundRobinEntrants + 1) * kMaxRoundRobinEntrants / 2 > kMaxTournamentMatches);

struct TournamentEntrantView {
  std::string name = {};
  std::string player = {};  ///< the entrant's key in lower-case hex
  int rating = 0;
  int seed = 0;   ///< 0 before the start
  int place = 0;  ///< 0 unknown
  bool withdrawn = false;
  bool operator==(const TournamentEntrantView&) const = default;
};

/// A match of the bracket; `state` 0 waiting, 1 ready, 2 in play, 3 decided.
struct TournamentMatchView {
  std::string round = {};
  int a = -1;
  int b = -1;
  int state = 0;
  int winner = -1;
  int racks_a = 0;
  int racks_b = 0;
  bool forfeit = false;
  std::string match = {};  ///< the server's match playing it, or empty
  int spot_a = 0;          ///< racks on the wire for a (a handicapped tournament)
  int spot_b = 0;
  bool operator==(const TournamentMatchView&) const = default;
};

struct TournamentView {
  std::string tournament = {};  ///< "<server id>-t<n>"
  std::string server = {};
  std::string name = {};
  TournamentFormat format = TournamentFormat::SingleElimination;
  rules::Game game = rules::Game::EightBall;
  int race_to = 1;
  TournamentPhase phase = TournamentPhase::Entry;
  int capacity = 0;
  std::vector<TournamentEntrantView> entrants = {};
  std::vector<TournamentMatchView> matches = {};
  int champion = -1;
  bool handicap = false;       ///< the lower-rated player of each match has racks on the wire
  std::string opened_by = {};  ///< the player who opened it; empty: the operator
  bool operator==(const TournamentView&) const = default;

  /// The index of the entrant with key `player` (hex), or -1.
  int entrantOf(const std::string& player) const {
    for (std::size_t i = 0; i < entrants.size(); ++i) {
      if (entrants[i].player == player) return static_cast<int>(i);
    }
    return -1;
  }
};

}  // namespace pool::protocol
