// Field by field between protocol::TournamentView and pool_TournamentInfo.
#include "net/tournament_convert.h"

#include <algorithm>

#include "net/wire_fields.h"

namespace pool::net {
namespace {

static_assert(pool_TOURNAMENT_ROUND_ROBIN ==
              static_cast<int>(protocol::TournamentFormat::RoundRobin));
static_assert(pool_TOURNAMENT_CANCELLED == static_cast<int>(protocol::TournamentPhase::Cancelled));

std::uint8_t byteOf(int v) {
  return static_cast<std::uint8_t>(std::clamp(v, 0, 255));
}

std::int16_t indexOf(int v) {
  return static_cast<std::int16_t>(std::clamp(v, -1, 32767));
}

}  // namespace

Sample<pool_TournamentInfo> toWire(const protocol::TournamentView& v) {
  Sample<pool_TournamentInfo> sample;
  pool_TournamentInfo& w = *sample;
  setText(w.tournament, v.tournament);
  setText(w.server, v.server);
  setText(w.name, v.name);
  setRawValue(w.format, static_cast<std::int32_t>(v.format));
  w.game = static_cast<std::uint8_t>(rules::gameNumber(v.game));
  w.race_to = byteOf(v.race_to);
  setRawValue(w.phase, static_cast<std::int32_t>(v.phase));
  w.capacity = byteOf(v.capacity);
  const auto ne =
      static_cast<std::uint32_t>(std::min(v.entrants.size(), protocol::kMaxTournamentEntrants));
  auto entrants = resizeSequence(w.entrants, ne);
  for (std::uint32_t i = 0; i < ne; ++i) {
    const auto& e = v.entrants[i];
    setText(entrants[i].name, e.name);
    setText(entrants[i].player, e.player);
    entrants[i].rating = static_cast<std::uint16_t>(std::clamp(e.rating, 0, 65535));
    entrants[i].seed = byteOf(e.seed);
    entrants[i].place = byteOf(e.place);
    entrants[i].withdrawn = e.withdrawn;
  }
  const auto nm =
      static_cast<std::uint32_t>(std::min(v.matches.size(), protocol::kMaxTournamentMatches));
  auto matches = resizeSequence(w.matches, nm);
  for (std::uint32_t i = 0; i < nm; ++i) {
    const auto& m = v.matches[i];
    setText(matches[i].round, m.round);
    matches[i].a = indexOf(m.a);
    matches[i].b = indexOf(m.b);
    matches[i].state = byteOf(m.state);
    matches[i].winner = indexOf(m.winner);
    matches[i].racks_a = byteOf(m.racks_a);
    matches[i].racks_b = byteOf(m.racks_b);
    matches[i].forfeit = m.forfeit;
    setText(matches[i].match, m.match);
    matches[i].spot_a = byteOf(m.spot_a);
    matches[i].spot_b = byteOf(m.spot_b);
  }
  w.champion = indexOf(v.champion);
  w.handicap = v.handicap;
  setText(w.opened_by, v.opened_by);
  return sample;
}

Result<protocol::TournamentView> fromWire(const pool_TournamentInfo& w) {
  using Out = Result<protocol::TournamentView>;
  if (!terminated(w.tournament) || !terminated(w.server) || !terminated(w.name) ||
      !terminated(w.opened_by)) {
    return Out::fail("tournament: a text past its bound");
  }
  protocol::TournamentView v;
  v.tournament = std::string(textOf(w.tournament));
  v.server = std::string(textOf(w.server));
  v.name = std::string(textOf(w.name));
  const std::int32_t format = rawValue(w.format);
  const std::int32_t phase = rawValue(w.phase);
  if (format < 0 || format > pool_TOURNAMENT_ROUND_ROBIN) return Out::fail("tournament: format");
  if (phase < 0 || phase > pool_TOURNAMENT_CANCELLED) return Out::fail("tournament: phase");
  v.format = static_cast<protocol::TournamentFormat>(format);
  v.phase = static_cast<protocol::TournamentPhase>(phase);
  const auto game = rules::gameOfNumber(w.game);
  if (!game) return Out::fail("tournament: unknown game " + std::to_string(w.game));
  v.game = *game;
  v.race_to = w.race_to;
  v.capacity = w.capacity;
  for (const auto& e : elementsOf(w.entrants)) {
    if (!terminated(e.name) || !terminated(e.player)) {
      return Out::fail("tournament: an entrant's text past its bound");
    }
    v.entrants.push_back({std::string(textOf(e.name)), std::string(textOf(e.player)), e.rating,
                          e.seed, e.place, e.withdrawn});
  }
  const int n = static_cast<int>(v.entrants.size());
  auto entrant = [n](int i) { return i >= -1 && i < n; };
  for (const auto& m : elementsOf(w.matches)) {
    if (!terminated(m.round) || !terminated(m.match)) {
      return Out::fail("tournament: a match's text past its bound");
    }
    if (!entrant(m.a) || !entrant(m.b) || !entrant(m.winner) || m.state > 3) {
      return Out::fail("tournament: a match names no entrant of it");
    }
    v.matches.push_back({std::string(textOf(m.round)), m.a, m.b, m.state, m.winner, m.racks_a,
                         m.racks_b, m.forfeit, std::string(textOf(m.match)), m.spot_a, m.spot_b});
  }
  if (!entrant(w.champion)) return Out::fail("tournament: the champion is no entrant of it");
  v.champion = w.champion;
  v.handicap = w.handicap;
  v.opened_by = std::string(textOf(w.opened_by));
  return Out::ok(std::move(v));
}

}  // namespace pool::net
