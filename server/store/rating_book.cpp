// Ratings in the store: a player's rating per game, and each decided match rated once.
#include "server/store/rating_book.h"

namespace pool::store {

bool isRated(const server::MatchSnapshot& m) {
  if (!m.started || m.settings.practice || m.game.phase != rules::Phase::Over) return false;
  if (m.game.winner != 0 && m.game.winner != 1) return false;
  const auto& a = m.seats[0].public_key;
  const auto& b = m.seats[1].public_key;
  return !a.empty() && !b.empty() && a != b;
}

rating::Rating ratingOf(Database& db, const std::vector<std::uint8_t>& key, rules::Game game) {
  auto q = db.prepare(
      "SELECT rating, deviation, volatility FROM ratings WHERE public_key = ? AND game = ?");
  q.bindBlob(1, key).bind(2, std::int64_t{rules::gameNumber(game)});
  if (!q.step()) return rating::Rating{};
  return rating::Rating{q.real(0), q.real(1), q.real(2)};
}

bool rateDecided(Database& db, const server::MatchSnapshot& m) {
  if (!isRated(m)) return false;
  auto seen =
      db.prepare("SELECT 1 FROM rated_results WHERE match = ? AND rack = ? AND shot_number = ?");
  seen.bind(1, m.id).bind(2, std::int64_t{m.rack}).bind(3, std::int64_t{m.shot_number});
  if (seen.step()) return false;
  const auto w = static_cast<std::size_t>(m.game.winner);
  const auto& winner_key = m.seats[w].public_key;
  const auto& loser_key = m.seats[1 - w].public_key;
  const std::int64_t game = rules::gameNumber(m.settings.game);
  const rating::Rating winner = ratingOf(db, winner_key, m.settings.game);
  const rating::Rating loser = ratingOf(db, loser_key, m.settings.game);
  const auto [winner_after, loser_after] = rating::afterMatch(winner, loser);
  auto put = db.prepare(
      "INSERT INTO ratings(public_key, game, rating, deviation, volatility, matches) "
      "VALUES(?, ?, ?, ?, ?, 1) ON CONFLICT(public_key, game) DO UPDATE SET "
      "rating = excluded.rating, deviation = excluded.deviation, "
      "volatility = excluded.volatility, matches = matches + 1");
  for (const auto& [key, r] : {std::pair{&winner_key, winner_after}, {&loser_key, loser_after}}) {
    put.bindBlob(1, *key)
        .bind(2, game)
        .bind(3, r.rating)
        .bind(4, r.deviation)
        .bind(5, r.volatility)
        .run();
    put.reset();
  }
  db.prepare(
        "INSERT INTO rated_results(match, rack, shot_number, game, winner_key, loser_key, "
        "winner_before, winner_after, loser_before, loser_after) "
        "VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?)")
      .bind(1, m.id)
      .bind(2, std::int64_t{m.rack})
      .bind(3, std::int64_t{m.shot_number})
      .bind(4, game)
      .bindBlob(5, winner_key)
      .bindBlob(6, loser_key)
      .bind(7, winner.rating)
      .bind(8, winner_after.rating)
      .bind(9, loser.rating)
      .bind(10, loser_after.rating)
      .run();
  return true;
}

std::vector<RatedResult> ratedResults(Database& db, const std::string& match) {
  std::vector<RatedResult> out;
  auto q = db.prepare(
      "SELECT rack, shot_number, game, winner_key, loser_key, winner_before, winner_after, "
      "loser_before, loser_after FROM rated_results WHERE match = ? ORDER BY rowid");
  q.bind(1, match);
  while (q.step()) {
    RatedResult r;
    r.match = match;
    r.rack = static_cast<std::uint32_t>(q.integer(0));
    r.shot_number = static_cast<std::uint32_t>(q.integer(1));
    const auto game = rules::gameOfNumber(q.integer(2));
    if (!game) throw StoreError("rated result of " + match + ": not a game");
    r.game = *game;
    r.winner_key = q.blob(3);
    r.loser_key = q.blob(4);
    r.winner_before = q.real(5);
    r.winner_after = q.real(6);
    r.loser_before = q.real(7);
    r.loser_after = q.real(8);
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace pool::store
