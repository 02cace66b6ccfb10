// The shot runner of each table a server plays on: its pool table, and the tables of the games
// that have their own (three-cushion's carom table), loaded when a match first needs them.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "core/result.h"
#include "rules/game_rules.h"
#include "server/match/shot_runner.h"

namespace pool::server {

/// Runners by table. The matches of a server share them, one shot at a time (the server's loop).
class TableRunners {
 public:
  /// `pool` plays the pool games (the server's --table); other tables load on first use.
  explicit TableRunners(std::shared_ptr<ShotRunner> pool);

  /// The runner of the table `game` is played on, loaded now if it was not yet, or why it cannot
  /// be ("table carom-match: ...").
  Result<std::shared_ptr<ShotRunner>> forGame(rules::Game game);

  const std::shared_ptr<ShotRunner>& pool() const { return pool_; }

 private:
  std::shared_ptr<ShotRunner> pool_;
  std::map<std::string, std::shared_ptr<ShotRunner>> others_;
};

}  // namespace pool::server
