// One accepted command as it is stored: the command, what it was judged on, what happened.
#pragma once

#include <cstdint>
#include <vector>

#include "physics/ball.h"
#include "physics/events.h"
#include "protocol/shot_request.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/verdict.h"

namespace pool::server {

/// An accepted shot (or a choice without a shot) with everything needed to judge or run it again.
struct ShotRecord {
  protocol::ShotRequest command;
  std::uint32_t shot_number = 0;      ///< the shot's number; a choice keeps the shots so far
  bool shoots = true;                 ///< false: a choice that re-racked, no physics
  rules::GameState state;             ///< the state it was judged in (any choice applied)
  std::vector<physics::Ball> before;  ///< the table at the strike (placement, respots applied)
  rules::Intent intent;
  physics::EventLog events;
  std::vector<physics::Ball> after;  ///< the physics' table at rest, before any respot
  rules::Verdict verdict;
};

}  // namespace pool::server
