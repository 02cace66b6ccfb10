// The tournaments a server runs: created by the operator or opened by players, entered by
// players with signed requests, their matches opened as ordinary matches with the drawn players'
// seats reserved, their results taken from those matches, kept in the store and published
// (TournamentInfo).
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "core/result.h"
#include "protocol/tournament_view.h"
#include "server/match/match_registry.h"
#include "server/store/match_store.h"
#include "server/tournament/tournament.h"

namespace pool::server {

/// How a tournament is played, as the operator creates it or a player opens it.
struct TournamentSetup {
  std::string name = {};
  protocol::TournamentFormat format = protocol::TournamentFormat::SingleElimination;
  rules::Game game = rules::Game::EightBall;
  int race_to = 1;   ///< racks (frames, games) each match is a race to, 1..15
  int capacity = 8;  ///< the entrants it takes, 3..32: it starts once that many entered
  /// The lower-rated player of each match starts with racks on the wire (tournament::
  /// handicapSpots of the two ratings at entry).
  bool handicap = false;
  std::string opened_by = {};                 ///< the player who opened it; empty: the operator
  std::vector<std::uint8_t> opener_key = {};  ///< their key
  /// The signature of the request that opened it: the same request again opens nothing more.
  std::vector<std::uint8_t> opening_signature = {};
};

/// Tournaments taking entries that players opened, at most, on one server (the operator's are
/// not counted); one of them a key, and one a DDS participant.
inline constexpr int kPlayerTournamentsOpen = 4;
/// Tournaments players opened that are not over, at most (those taking entries and those running):
/// the rest of kMaxTournaments is the operator's.
inline constexpr int kPlayerTournamentsNotOver = 8;
/// How long a tournament a player opened takes entries, s: then it starts with those in (3 at
/// least) or is cancelled (a restart gives it this long again).
inline constexpr double kPlayerEntryWindow = 15 * 60.0;

/// Entries one DDS participant may make in one tournament (keys cost nothing: a participant that
/// makes many is still one asking).
inline constexpr int kEntriesPerParticipant = 2;
/// Tournaments a server holds at once, at most: past it, those over longest ago are forgotten
/// (kept in the store), and none is created while as many are not over.
inline constexpr std::size_t kMaxTournaments = 64;

/// Not thread-safe; time is passed in (s, the server's monotonic clock).
class TournamentDesk {
 public:
  /// With a null `store` nothing is kept (a restart forgets the tournaments).
  TournamentDesk(MatchRegistry& registry, store::MatchStore* store);

  /// Restores every stored tournament (at start, after the matches were resumed).
  void restore();

  /// A new tournament taking entries; its id ("<server id>-t<n>"), or why not.
  Result<std::string> create(const TournamentSetup& setup);
  /// Starts `id` with the entrants in so far (at least 3).
  Check<> start(const std::string& id);
  /// Cancels `id`: its matches in play go on as ordinary matches (their ids are answered).
  Result<std::vector<std::string>> cancel(const std::string& id);

  /// Whether `id` names a tournament of this server (a join request's match field may).
  bool isTournament(const std::string& id) const { return tournaments_.count(id) > 0; }
  /// An entry (JoinAction::Enter, the registry's checks of version, name, key and signature
  /// made here too): the signing key enters under the request's name; entering again is accepted
  /// unchanged. Refused once the tournament has started, when it is full, or past
  /// kEntriesPerParticipant entries from `sender`.
  /// An entry into protocol::kNewMatch with settings (game, race) and an opening (format,
  /// entrants, handicap) opens a tournament ("<name>'s cup") that the signer enters first; the
  /// answer names it. Refused past kPlayerTournamentsOpen taking entries, or when the key or
  /// `sender` has one taking entries already.
  JoinAnswer enter(const JoinCommand& command, const std::string& sender);

  /// Takes the decided matches' results, opens the matches that are ready (as far as the
  /// registry has room), starts a tournament that is full. Changes are stored at once.
  void step(double now);

  /// Every tournament as published.
  std::vector<protocol::TournamentView> views() const;
  /// The tournaments changed since the last call (to publish).
  std::vector<protocol::TournamentView> takeChanged();

 private:
  struct Entry {
    std::string name;
    std::vector<std::uint8_t> key;
    double rating = 1500.0;
    std::string sender;        ///< the DDS participant it came from (not stored)
    double deviation = 350.0;  ///< its rating's, at entry
  };
  struct Held {
    std::string id;
    std::uint64_t number = 0;
    TournamentSetup setup;
    protocol::TournamentPhase phase = protocol::TournamentPhase::Entry;
    std::vector<Entry> entries;
    std::optional<tournament::Tournament> bracket;  ///< once started
    std::vector<std::string> match_ids;             ///< by bracket match index
    std::string opener_sender;  ///< the DDS participant a player opened it from (not stored)
    std::optional<double> entry_since;  ///< a player's: taking entries since (s, this run)
    bool changed = true;
  };

  JoinAnswer open(const JoinCommand& command, const std::string& sender);
  /// Adds the signer of `command` (checked) to `held` from `sender`.
  JoinAnswer addEntry(Held& held, const JoinCommand& command, const std::string& sender);
  /// Racks on the wire for the entrants of bracket match `index` (none without a handicap).
  std::array<int, 2> spotsOf(const Held& held, int a, int b) const;
  Check<> startHeld(Held& held);
  /// Forgets the tournaments over longest ago (kept in the store) while kMaxTournaments are held.
  void forgetOldest();
  void stepHeld(Held& held, double now);
  protocol::TournamentView viewOf(const Held& held) const;
  void save(const Held& held);

  MatchRegistry& registry_;
  store::MatchStore* store_;
  std::map<std::string, Held> tournaments_;
  std::uint64_t opened_ = 0;
};

}  // namespace pool::server
