// Statistics in the store: a stroke's pots, fouls, safeties and runs, and racks and matches won.
#include "server/store/stat_book.h"

#include <algorithm>

namespace pool::store {
namespace {

constexpr const char* kColumns =
    "public_key, game, name, matches, matches_won, racks, racks_won, strokes, attempts, pots, "
    "breaks, break_pots, break_and_runs, fouls, safeties, high_run";

/// A seat's statistics and its inning in play in this match (its run; whether it began with the
/// seat's own break and nobody else has played since).
struct Row {
  PlayerStats stats;
  int run = 0;
  bool from_break = false;
};

Row rowAt(const Statement& q) {
  Row row;
  PlayerStats& s = row.stats;
  s.key = q.blob(0);
  s.game = rules::gameOfNumber(static_cast<int>(q.integer(1))).value_or(rules::Game::EightBall);
  s.name = q.text(2);
  int* counts[] = {&s.matches,  &s.matches_won, &s.racks,   &s.racks_won,  &s.strokes,
                   &s.attempts, &s.pots,        &s.breaks,  &s.break_pots, &s.break_and_runs,
                   &s.fouls,    &s.safeties,    &s.high_run};
  int column = 3;
  for (int* c : counts) *c = static_cast<int>(q.integer(column++));
  return row;
}

std::optional<Row> readRow(Database& db, const std::vector<std::uint8_t>& key, rules::Game game) {
  auto q = db.prepare(std::string("SELECT ") + kColumns +
                      " FROM player_stats WHERE public_key = ? AND game = ?");
  q.bindBlob(1, key).bind(2, std::int64_t{rules::gameNumber(game)});
  if (!q.step()) return std::nullopt;
  return rowAt(q);
}

/// Seat `index` of `match`: its player's statistics in the match's game and the seat's inning.
Row rowOf(Database& db, const server::MatchSnapshot& match, std::size_t index) {
  const server::Seat& seat = match.seats[index];
  Row row = readRow(db, seat.public_key, match.settings.game).value_or(Row{});
  row.stats.key = seat.public_key;
  row.stats.game = match.settings.game;
  row.stats.name = seat.player;
  auto q = db.prepare("SELECT run, from_break FROM stat_innings WHERE match = ? AND seat = ?");
  q.bind(1, match.id).bind(2, static_cast<std::int64_t>(index));
  if (q.step()) {
    row.run = static_cast<int>(q.integer(0));
    row.from_break = q.integer(1) != 0;
  }
  return row;
}

void writeRow(Database& db, const Row& row, const std::string& match, std::size_t index) {
  const PlayerStats& s = row.stats;
  auto put = db.prepare(std::string("INSERT OR REPLACE INTO player_stats(") + kColumns +
                        ", updated) VALUES(?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, ?, "
                        "(SELECT COALESCE(MAX(updated), 0) + 1 FROM player_stats))");
  put.bindBlob(1, s.key).bind(2, std::int64_t{rules::gameNumber(s.game)}).bind(3, s.name);
  const int counts[] = {s.matches,  s.matches_won, s.racks,   s.racks_won,  s.strokes,
                        s.attempts, s.pots,        s.breaks,  s.break_pots, s.break_and_runs,
                        s.fouls,    s.safeties,    s.high_run};
  int column = 4;
  for (int c : counts) put.bind(column++, std::int64_t{c});
  put.run();
  db.prepare("INSERT OR REPLACE INTO stat_innings(match, seat, run, from_break) VALUES(?, ?, ?, ?)")
      .bind(1, match)
      .bind(2, static_cast<std::int64_t>(index))
      .bind(3, std::int64_t{row.run})
      .bind(4, std::int64_t{row.from_break ? 1 : 0})
      .run();
}

/// What a stroke scored toward a run: legal pots in pool, the points in snooker and
/// three-cushion.
int gained(const rules::Verdict& v, rules::Game game) {
  if (!rules::isPool(game)) return v.scored;
  return v.legal() ? static_cast<int>(v.pocketed.size()) : 0;
}

}  // namespace

bool countsForStats(const server::MatchSnapshot& m) {
  if (m.settings.practice) return false;
  const auto& a = m.seats[0].public_key;
  const auto& b = m.seats[1].public_key;
  return !a.empty() && !b.empty() && a != b;
}

void countStroke(Database& db, const server::ShotRecord& record,
                 const server::MatchSnapshot& after) {
  if (!countsForStats(after)) return;
  const int seat = record.command.seat;
  if (seat != 0 && seat != 1) return;
  const rules::Game game = after.settings.game;
  const rules::Verdict& v = record.verdict;
  std::array<Row, 2> rows{rowOf(db, after, 0), rowOf(db, after, 1)};
  Row& me = rows[static_cast<std::size_t>(seat)];
  Row& other = rows[static_cast<std::size_t>(1 - seat)];
  PlayerStats& s = me.stats;
  if (record.shoots) {
    ++s.strokes;
    const int got = gained(v, game);
    const bool is_break = record.state.phase == rules::Phase::Break;
    const bool push_out = record.intent.choice == rules::Choice::PushOut;
    if (is_break) {
      ++s.breaks;
      s.break_pots += got;
      me.run = got;
      me.from_break = v.legal();  // a break that passes the turn ends the inning below
    } else {
      if (record.intent.safety) {
        ++s.safeties;
      } else if (!push_out) {
        ++s.attempts;
        s.pots += got;
      }
      me.run = v.legal() ? me.run + got : 0;
    }
    s.high_run = std::max(s.high_run, me.run);
    // Whoever was at the table before this stroke is no longer in an inning of their own.
    other.run = 0;
    other.from_break = false;
  }
  // A foul ends the inning, a stroke's or the shot clock's run out before one.
  if (!v.legal()) {
    ++s.fouls;
    me.run = 0;
    me.from_break = false;
  }
  if (v.game_over && (v.winner == 0 || v.winner == 1)) {
    const auto w = static_cast<std::size_t>(v.winner);
    for (Row& row : rows) ++row.stats.racks;
    ++rows[w].stats.racks_won;
    // The rack's last stroke ends the inning: a break-and-run when it began with the break.
    if (static_cast<int>(w) == seat && record.shoots && me.from_break) ++s.break_and_runs;
    if (after.game.phase == rules::Phase::Over) {
      for (Row& row : rows) ++row.stats.matches;
      ++rows[w].stats.matches_won;
    }
    for (Row& row : rows) {
      row.run = 0;
      row.from_break = false;
    }
  } else if (record.shoots && !v.turn_continues) {
    me.run = 0;
    me.from_break = false;
  }
  writeRow(db, rows[0], after.id, 0);
  writeRow(db, rows[1], after.id, 1);
}

std::optional<PlayerStats> statsOf(Database& db, const std::vector<std::uint8_t>& key,
                                   rules::Game game) {
  const auto row = readRow(db, key, game);
  if (!row) return std::nullopt;
  return row->stats;
}

std::vector<PlayerStats> recentStats(Database& db, std::size_t limit) {
  auto q = db.prepare(std::string("SELECT ") + kColumns +
                      " FROM player_stats ORDER BY updated DESC LIMIT ?");
  q.bind(1, static_cast<std::int64_t>(limit));
  std::vector<PlayerStats> out;
  while (q.step()) out.push_back(rowAt(q).stats);
  return out;
}

}  // namespace pool::store
