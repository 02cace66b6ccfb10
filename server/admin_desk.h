// The operator's orders carried out on a running server: list, close, ban, backup, status,
// tournaments.
#pragma once

#include <chrono>
#include <string>

#include "server/admin/admin_request.h"
#include "server/match/match_registry.h"
#include "server/server_counters.h"
#include "server/store/match_store.h"
#include "server/tournament_desk.h"

namespace pool::server {

/// Answers admin requests from the server's loop, on its thread, between passes. Orders that
/// change something (close, ban, unban) change the registry and the store; the loop then stores
/// and publishes the matches they touched as usual (a closed match's players read it in its
/// MatchState before it is disposed).
class AdminDesk {
 public:
  AdminDesk(MatchRegistry& registry, store::MatchStore& store, const ServerCounters& counters,
            std::string db_path);

  /// Loads the bans kept in the store into the registry (at start).
  void loadBans();
  /// The tournaments the tournament verbs act on (without: they are refused).
  void tournaments(TournamentDesk* desk) { tournaments_ = desk; }

  /// The reply to `request` line: {"ok":true, ...} or {"ok":false,"error":"..."}; a request that
  /// does not parse, or names nothing that exists, changes nothing.
  struct Reply {
    bool ok = false;
    std::string line;
  };
  Reply answer(const std::string& request);

 private:
  std::string status() const;
  std::string list();
  std::string close(const admin::AdminRequest& r);
  std::string ban(const admin::AdminRequest& r);
  std::string unban(const admin::AdminRequest& r);
  std::string bans();
  std::string backup(const admin::AdminRequest& r);
  std::string createTournament(const admin::AdminRequest& r);
  std::string startTournament(const admin::AdminRequest& r);
  std::string cancelTournament(const admin::AdminRequest& r);
  std::string listTournaments() const;

  MatchRegistry& registry_;
  store::MatchStore& store_;
  const ServerCounters& counters_;
  std::string db_path_;
  TournamentDesk* tournaments_ = nullptr;
  std::chrono::steady_clock::time_point started_;
};

/// {"ok":false,"error":why} as one line.
std::string adminError(const std::string& why);

}  // namespace pool::server
