// A match as plain data between shots: what persistence stores and a restarted server resumes.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "physics/ball.h"
#include "protocol/match_settings.h"
#include "rules/game_state.h"
#include "server/match/seat.h"
#include "table/rack.h"

namespace pool::server {

/// Everything a match needs to go on from where it stood at rest (spectators and presence are
/// not kept: a resumed match shows every seated player away until they rejoin).
struct MatchSnapshot {
  std::string id;
  std::string name;
  std::uint64_t number = 0;     ///< n of the id "<server id>-<n>"
  std::uint64_t rack_seed = 0;  ///< seed of the match's racks
  std::uint64_t layouts = 0;    ///< racks laid out so far
  /// How its racks are laid out (Frozen for matches stored before racks had gaps).
  table::RackGenerator rack_generator = table::RackGenerator::Frozen;
  bool started = false;
  bool closed = false;
  bool client_made = false;  ///< opened by a join to "new" (closed once empty)
  std::uint32_t shot_number = 0;
  std::uint32_t rack = 0;
  std::uint64_t revision = 1;
  std::string last_verdict;
  rules::GameState game;
  std::vector<physics::Ball> balls;  ///< at rest, id order
  std::array<Seat, 2> seats{};
  protocol::MatchSettings settings;  ///< game, race, breaks, shot clock
};

}  // namespace pool::server
