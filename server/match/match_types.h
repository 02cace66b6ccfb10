// What a match reports: its phase, its options, and the answers to commands (domain terms).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include "physics/events.h"
#include "protocol/match_settings.h"
#include "protocol/protocol_enums.h"
#include "rules/eight_ball.h"
#include "rules/verdict.h"
#include "server/match/reject.h"
#include "server/match/shot_record.h"
#include "server/match/table_runners.h"

namespace pool::server {

using protocol::MatchPhase;  ///< where a match stands (shared with the clients)

/// How a match is played and published.
struct MatchOptions {
  double snapshot_hz = 60.0;    ///< frames per simulated second (> 0)
  bool unpaced = false;         ///< every frame due as soon as the shot is accepted
  double max_shot_time = 60.0;  ///< bound on a shot's simulated time, s
  rules::EightBallConfig rules;
  /// How a table is played unless the player who opens it says otherwise (`pool-server --game,
  /// --race, --breaks, --shot-clock`).
  protocol::MatchSettings settings;
  /// The runner of each game's table (three-cushion plays on its own); null: every game on the
  /// runner the match was made with.
  std::shared_ptr<TableRunners> tables;
};

/// What the shooter's view still shows of a shot after its last frame is due: the clients play
/// frames back 0.1 s behind their arrival; the shot clock starts once that is over.
inline constexpr double kViewDelay = 0.1;

/// An accepted command once it is done: its events (none for a choice without a shot) and the
/// verdict.
struct ShotReport {
  int seat = 0;
  std::uint32_t seq = 0;
  std::uint32_t shot_number = 0;  ///< shots of the match so far, this one included
  physics::EventLog events;
  rules::Verdict verdict;
  std::string text;  ///< a practice change's line (instead of the verdict's)
};

/// The immediate answer to a shot command.
struct CommandAnswer {
  Rejection rejection;               ///< reason None: accepted
  int seat = 0;                      ///< as the command gave it
  std::uint32_t seq = 0;             ///< as the command gave it
  std::uint32_t shot_number = 0;     ///< accepted: the shot's number; rejected: shots so far
  bool in_motion = false;            ///< accepted shot: frames follow, then Match::finishShot
  std::optional<ShotReport> done;    ///< accepted choice without a shot: done already
  std::optional<ShotRecord> record;  ///< accepted: what to store before answering

  bool accepted() const { return rejection.accepted(); }
};

}  // namespace pool::server
