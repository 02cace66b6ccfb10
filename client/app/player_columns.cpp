// The Players table's columns: a player's rating and counts, short.
#include "client/app/player_columns.h"

#include <cmath>
#include <cstdio>

namespace pool::app {

const std::array<const char*, kPlayerColumns>& playerHeaders() {
  static const std::array<const char*, kPlayerColumns> kHeaders{"server",
                                                                "player",
                                                                "game",
                                                                "rating",
                                                                "matches won",
                                                                "racks won",
                                                                "pots / attempts",
                                                                "breaks: pots, runs",
                                                                "fouls",
                                                                "safeties",
                                                                "best inning"};
  return kHeaders;
}

std::array<std::string, kPlayerColumns> playerColumns(const protocol::PlayerStats& s) {
  const auto of = [](int a, int b) { return std::to_string(a) + "/" + std::to_string(b); };
  std::string pots = of(s.pots, s.attempts);
  if (s.attempts > 0) {
    // Balls (or points) an attempt: one stroke can pot two balls, so a share of the attempts
    // could pass 100 %.
    char per[32];
    std::snprintf(per, sizeof per, "%.2f", static_cast<double>(s.pots) / s.attempts);
    pots += std::string(", ") + per + " an attempt";
  }
  return {s.server,
          s.name,
          rules::toString(s.game),
          std::to_string(s.rating) + " ±" + std::to_string(s.rating_deviation),
          of(s.matches_won, s.matches),
          of(s.racks_won, s.racks),
          pots,
          std::to_string(s.breaks) + ": " + std::to_string(s.break_pots) + ", " +
              std::to_string(s.break_and_runs) + (s.break_and_runs == 1 ? " run" : " runs"),
          std::to_string(s.fouls),
          std::to_string(s.safeties),
          std::to_string(s.high_run)};
}

}  // namespace pool::app
