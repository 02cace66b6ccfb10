// A tournament as a pool server runs it: 3 to 32 entrants, one format, played to a champion.
//
// Matches are started one by one as tables free up, reported, and lead to final standings.
//
// Formats:
//   - single elimination: a bracket of the next power of two, seeded 1 v N, 2 v N-1, ... so that
//     seeds 1 and 2 meet in the final at the earliest; byes go to the top seeds (no match).
//   - double elimination: the same winners' bracket, a losers' bracket, and a grand final of one
//     match plus a reset match if the losers'-bracket finalist wins it (as WPA and most pool
//     double-elimination events play it): nobody is out before two losses. 2N-2 matches, or 2N-1
//     with the reset.
//   - round robin: every entrant meets every other once (circle method), ranked by wins, then the
//     wins among those level on wins (a mini-table; head-to-head for two), then rack difference,
//     then seed (see round_robin.h). N(N-1)/2 matches.
// Seeds follow the ratings, highest first, equal ratings in entry order. Entrants and matches are
// named by index: entrants in the order given, matches by their number in matches().
// A forfeit is a match (decided 0-0, marked forfeit), so the match counts above hold with forfeits;
// a grand final lost by forfeit by the winners' bracket champion is followed by a reset that they
// forfeit too.
#pragma once

#include "core/check.h"
#include "core/result.h"
#include "server/tournament/entrant.h"
#include "server/tournament/event.h"
#include "server/tournament/match.h"
#include "server/tournament/standings.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pool::tournament {

enum class Format : std::uint8_t { SingleElimination, DoubleElimination, RoundRobin };

struct Options {
  /// The racks a match is played to (a race to raceTo): a report must give the winner exactly
  /// raceTo racks and the loser fewer. 0: any score where the winner won more racks.
  int raceTo = 0;
};

class Tournament {
 public:
  /// A new tournament, nothing played; refuses a field checkEntrants() refuses ("bad_entrants"),
  /// an unknown format or a negative raceTo ("bad_options").
  static Result<Tournament> create(Format format, std::vector<Entrant> entrants,
                                   Options options = {});

  /// The tournament as one JSON text (its field, options and log of calls, plus the matches for
  /// people reading it): what a server stores to restore it after a restart.
  std::string toJson() const;
  /// The tournament toJson() wrote; refuses text that is not such a tournament, or whose log does
  /// not replay to its matches, with code "bad_json" and one line.
  static Result<Tournament> fromJson(const std::string& text);

  Format format() const { return format_; }
  const Options& options() const { return options_; }
  const std::vector<Entrant>& entrants() const { return entrants_; }
  /// Entrant `entrant`'s seed, 1 the best.
  int seed(int entrant) const { return seeds_[entrant]; }
  /// Every match so far, by number. Elimination brackets hold all their matches from the start
  /// (Waiting until their entrants are known), but for the grand final's reset, added when needed.
  const std::vector<Match>& matches() const { return matches_; }
  /// The calls that made this state, in order.
  const std::vector<Event>& log() const { return log_; }
  /// Whether the entrant has left (forfeit).
  bool withdrawn(int entrant) const { return withdrawn_[entrant]; }

  /// The matches that may start now, by number (the earlier rounds first): both entrants known,
  /// not started, neither entrant in play elsewhere. Empty once the tournament is over.
  std::vector<int> readyMatches() const;
  /// Marks a ready match in play. Refuses (codes): "over" (finished or cancelled),
  /// "unknown_match", "not_ready" (an entrant not known yet), "in_play", "reported",
  /// "entrant_busy" (an entrant is in play in another match).
  Check<> start(int match);
  /// The result of a match in play: `winner` (an entrant index) and the racks each side won
  /// (racksA for the match's entrant a). Refuses: "over", "unknown_match", "not_in_play" (not
  /// started), "reported" (already reported), "not_in_match" (the winner is not one of the two),
  /// "bad_racks" (negative, the winner not ahead, or not the race's score).
  Check<> report(int match, int winner, int racksA, int racksB);
  /// Entrant `entrant` has left: their match in play or ready is lost by forfeit, and so is every
  /// later one of theirs as soon as its other entrant is known (in round robin, every remaining
  /// match of theirs at once). A match between two who left goes to its entrant a. Answers the
  /// matches this decided, by number (those in play among them should be stopped). Refuses
  /// "over", "unknown_entrant", "withdrawn" (already left).
  Result<std::vector<int>> forfeit(int entrant);
  /// Ends the tournament without a champion. The matches in play are left to finish as ordinary
  /// matches: the tournament forgets them (they stay InPlay, and report() refuses them as "over").
  /// Answers their numbers. Refuses "over".
  Result<std::vector<int>> cancel();

  bool finished() const { return champion_.has_value(); }
  bool cancelled() const { return cancelled_; }
  /// The winner, once finished.
  std::optional<int> champion() const { return champion_; }
  /// Every entrant's record and place, best first. Elimination: places by the round an entrant
  /// went out in, shared (1st, 2nd, 3rd-4th, 5th-8th, ...; while it runs, everyone still in is
  /// 1st). Round robin: the ranking, 1 to N.
  std::vector<Standing> standings() const;

 private:
  Tournament() = default;
  Check<> checkRunning(const char* call) const;
  /// Records a match's result and moves its winner and loser on.
  void decide(int match, int winner, int racksA, int racksB, bool forfeit);
  /// Decides by forfeit every ready or in-play match of an entrant who left; answers them.
  std::vector<int> settleForfeits();

  Format format_ = Format::SingleElimination;
  Options options_ = {};
  std::vector<Entrant> entrants_;
  std::vector<int> seeds_;  ///< by entrant
  std::vector<Match> matches_;
  std::vector<bool> withdrawn_;
  std::vector<Event> log_;
  std::optional<int> champion_;
  bool cancelled_ = false;
};

}  // namespace pool::tournament
