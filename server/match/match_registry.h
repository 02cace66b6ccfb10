// The lobby: every match of one server, with unique ids, joins and leaves, and presence.
#pragma once

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "core/result.h"
#include "protocol/practice_request.h"
#include "protocol/shot_request.h"
#include "server/match/join.h"
#include "server/match/match.h"
#include "server/match/match_types.h"
#include "server/match/shot_runner.h"
#include "server/match/token_source.h"

namespace pool::server {

/// How a registry runs its matches.
struct RegistryOptions {
  std::string server_id;          ///< prefix of every match id; empty: 8 random hex digits
  std::string table = "wpa-9ft";  ///< table spec of every match
  MatchOptions match;
  std::size_t max_matches = 256;       ///< "new" beyond this is refused (server full)
  std::uint32_t protocol_version = 2;  ///< a join with another version is refused
  std::uint64_t seed = 0;              ///< tokens and racks; 0: from the OS entropy source
  /// Non-zero: match n's racks come from seed rack_seed + n, so a session's racks can be played
  /// again (pool-server --rack-seed); 0: each match's seed is random.
  std::uint64_t rack_seed = 0;
};

/// Owns the matches of one server. Match ids are "<server id>-<n>", n counting from 1 and never
/// reused. Pure logic: time comes in as `now` (s, monotonic).
class MatchRegistry {
 public:
  /// A registry playing on `kit` (loaded once with game::loadSharedTable).
  MatchRegistry(RegistryOptions options, std::shared_ptr<const game::LoadedTable> kit);

  const std::string& serverId() const { return server_id_; }
  const RegistryOptions& options() const { return options_; }
  /// The table every match of this registry is played on.
  const game::LoadedTable& table() const { return runner_->kit(); }

  /// Opens an empty match named `name` (default "Table <n>") whose racks `generator` lays out
  /// from `rack_seed` (default: random); null when the server is full.
  Match* open(std::string name = {}, std::optional<std::uint64_t> rack_seed = {},
              table::RackGenerator generator = table::kCurrentRackGenerator);
  /// The open match of `id`, or null.
  Match* find(std::string_view id);
  /// Every open match, oldest first.
  std::vector<Match*> matches();

  /// Matches opened so far (the n of the latest id).
  std::uint64_t opened() const { return opened_; }
  /// Numbers the next match from `count` + 1 on (a restarted server: ids are never reused).
  void continueAfter(std::uint64_t count) { opened_ = std::max(opened_, count); }
  /// Resumes a stored match at `now` (its players away from then on); null when the server is
  /// full or the id is open already.
  Match* adopt(const MatchSnapshot& snapshot, double now);
  /// `match` as plain data, with its number and whether a client made it.
  MatchSnapshot snapshotOf(const Match& match) const;

  /// Answers a join request (the JoinAction's meaning is in join.h).
  JoinAnswer join(const JoinCommand& command);
  /// Routes a shot command to its match (refused with NoSuchMatch when there is none). The wire
  /// fields were checked before (net's validateShotCommand).
  CommandAnswer shoot(const protocol::ShotRequest& command, double now);
  /// Routes a practice command to its match, as shoot does (Match::handlePractice).
  CommandAnswer practice(const protocol::PracticeRequest& command, double now);

  /// `client` vanished at `now`: its seats wait `grace` s for it, it stops watching. True when it
  /// held a seat anywhere.
  bool clientGone(const std::string& client, double now);
  /// Whether a seat of some match names `client` (away or not).
  bool seats(const std::string& client) const;
  /// Spectators over every match (a client watching two matches counts twice).
  std::size_t spectators() const;
  /// The server was not running for `seconds` (see Match::pause).
  void pause(double seconds);
  /// Applies grace expiries due by `now` (forfeits, freed lobby seats).
  void expireAway(double now, double grace);
  /// Runs every match's shot clock at `now` (Match::tickClock): the expiries judged, with their
  /// match ids, to store and publish.
  std::vector<std::pair<std::string, CommandAnswer>> tickClocks(double now);
  /// Closes matches that clients created, and finished ones, once nobody sits in or watches them,
  /// and drops those closed otherwise (closeMatch); returns their ids. Empty tables opened by
  /// open() stay.
  std::vector<std::string> sweepEmpty();
  /// Opens matches until `count` tables are free (in the lobby, nobody seated), as far as
  /// max_matches allows; returns how many it opened.
  int keepFreeTables(int count);

  /// Closes open match `id` at once (an operator's order): a shot in motion stops, its players
  /// read `why` as the last verdict; the next sweepEmpty drops it. False when no such match.
  bool closeMatch(std::string_view id, const std::string& why);

  /// Bans `key`: its seat requests (but a leave) and its seat's shot commands are refused with
  /// `reason`. A key banned already keeps its first reason.
  void ban(const std::vector<std::uint8_t>& key, const std::string& reason);
  /// Lifts the ban of `key`; false when it was not banned.
  bool unban(const std::vector<std::uint8_t>& key);
  /// The reason `key` is banned, or null.
  const std::string* banReason(const std::vector<std::uint8_t>& key) const;

  /// The earliest frame due among the matches in motion (s), or empty.
  std::optional<double> nextFrameDue() const;

 private:
  /// A command to its match (banned keys and unknown matches refused), its key's floor raised.
  template <class Command, class Handle>
  CommandAnswer route(const Command& command, Handle&& handle);
  JoinAnswer seat(const JoinCommand& command);
  JoinAnswer spectate(const JoinCommand& command);
  JoinAnswer leave(const JoinCommand& command);
  /// The refusal of a seat request signed with a banned key, or empty.
  std::optional<JoinAnswer> bannedSeat(const JoinCommand& command) const;
  /// The last seq `key` used on this server (0: none seen).
  std::uint32_t keyFloor(const std::vector<std::uint8_t>& key) const;
  /// Records that `key` used `seq` (the floor only rises).
  void useKeySeq(const std::vector<std::uint8_t>& key, std::uint32_t seq);

  RegistryOptions options_;
  TokenSource random_;
  std::string server_id_;
  std::shared_ptr<ShotRunner> runner_;
  std::vector<std::unique_ptr<Match>> matches_;
  std::set<std::string> client_made_;  ///< ids of matches created by a join to "new"
  std::uint64_t opened_ = 0;
  /// Per public key, the last seq it used here: a seat request replayed after its player left
  /// cannot seat them again. Seeded from the seats of resumed matches.
  std::map<std::vector<std::uint8_t>, std::uint32_t> key_seq_;
  std::map<std::vector<std::uint8_t>, std::string> banned_;  ///< key -> the operator's reason
};

/// A player name is 1–31 bytes of well-formed UTF-8 without control characters ("Zoë" is one).
bool validPlayerName(std::string_view name);

}  // namespace pool::server
