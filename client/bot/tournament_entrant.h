// pool-bot in a tournament: it enters, then plays each match the bracket gives it (one BotPlayer
// a match, through the same client), until the tournament is over.
#pragma once

#include <memory>
#include <optional>
#include <set>
#include <string>

#include "client/bot/bot_player.h"
#include "client/net/game_client.h"

namespace pool::bot {

/// Plays tournament `tournament` through `client`. Time is passed in (s on any monotonic clock).
class TournamentEntrant {
 public:
  TournamentEntrant(client::GameClient& client, BotConfig config, std::string tournament);

  /// Handles what arrived since the last step and acts on it.
  void step(double now);

  bool done() const { return stage_ == Stage::Done || stage_ == Stage::Failed; }
  bool failed() const { return stage_ == Stage::Failed; }
  /// "tournament srv-t1 finished: champion (3 matches won)" once done.
  const std::string& resultLine() const { return result_line_; }
  const std::string& failure() const { return failure_; }

 private:
  enum class Stage { Entering, Waiting, Playing, Done, Failed };

  void enter(double now);
  void wait();
  /// Our place in the tournament as the latest bracket says it: -1 when we are not in it.
  int me(const protocol::TournamentView& view) const;

  client::GameClient& client_;
  BotConfig config_;
  std::string tournament_;
  Stage stage_ = Stage::Entering;
  std::optional<std::uint32_t> request_;
  double sent_at_ = -1e9;
  std::unique_ptr<BotPlayer> player_;  ///< the match being played
  std::string playing_;                ///< its id
  std::set<std::string> played_;       ///< the matches played to their end
  int won_ = 0;
  std::string result_line_;
  std::string failure_;
};

}  // namespace pool::bot
