// Field by field between protocol::PlayerStats and pool_PlayerStats.
#include "net/player_stats_convert.h"

#include <algorithm>
#include <array>
#include <limits>

#include "core/hex.h"
#include "net/wire_fields.h"

namespace pool::net {
namespace {

/// The counts, in the wire's order, of a domain record (or a const one).
template <class Stats>
auto countsOf(Stats& s) {
  return std::array{&s.matches,  &s.matches_won, &s.racks,   &s.racks_won,  &s.strokes,
                    &s.attempts, &s.pots,        &s.breaks,  &s.break_pots, &s.break_and_runs,
                    &s.fouls,    &s.safeties,    &s.high_run};
}

template <class Wire>
auto wireCountsOf(Wire& w) {
  return std::array{&w.matches,  &w.matches_won, &w.racks,   &w.racks_won,  &w.strokes,
                    &w.attempts, &w.pots,        &w.breaks,  &w.break_pots, &w.break_and_runs,
                    &w.fouls,    &w.safeties,    &w.high_run};
}

std::uint16_t shortOf(int v) {
  return static_cast<std::uint16_t>(std::clamp(v, 0, 65535));
}

}  // namespace

Sample<pool_PlayerStats> toWire(const protocol::PlayerStats& stats) {
  Sample<pool_PlayerStats> sample;
  pool_PlayerStats& w = *sample;
  setText(w.server, stats.server);
  setText(w.player, hexOf(stats.key));
  w.game = static_cast<std::uint8_t>(rules::gameNumber(stats.game));
  setText(w.name, stats.name);
  w.rating = shortOf(stats.rating);
  w.rating_deviation = shortOf(stats.rating_deviation);
  const auto from = countsOf(stats);
  const auto to = wireCountsOf(w);
  for (std::size_t i = 0; i < from.size(); ++i) {
    *to[i] = static_cast<std::uint32_t>(std::max(0, *from[i]));
  }
  return sample;
}

Result<protocol::PlayerStats> fromWire(const pool_PlayerStats& w) {
  using Out = Result<protocol::PlayerStats>;
  if (!terminated(w.server) || !terminated(w.player) || !terminated(w.name)) {
    return Out::fail("player stats: a text past its bound");
  }
  protocol::PlayerStats s;
  s.server = std::string(textOf(w.server));
  const std::string hex(textOf(w.player));
  const auto key = bytesFromHex(hex);
  if (hex.size() != 64 || !key) return Out::fail("player stats: the player is not a key in hex");
  s.key = *key;
  const auto game = rules::gameOfNumber(w.game);
  if (!game) return Out::fail("player stats: unknown game " + std::to_string(w.game));
  s.game = *game;
  s.name = std::string(textOf(w.name));
  s.rating = w.rating;
  s.rating_deviation = w.rating_deviation;
  const auto from = wireCountsOf(w);
  const auto to = countsOf(s);
  for (std::size_t i = 0; i < from.size(); ++i) {
    *to[i] = static_cast<int>(std::min<std::uint32_t>(*from[i], std::numeric_limits<int>::max()));
  }
  return Out::ok(std::move(s));
}

}  // namespace pool::net
