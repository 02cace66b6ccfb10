// Statistics in a real SQLite file: a scripted race of 9-ball whose every stroke the test knows
// (pots, fouls, a safety, breaks, a break-and-run) stored stroke by stroke; the counts each player
// ends with are worked out here by hand from the script. Practice and hot-seat play are not
// counted.
#include <gtest/gtest.h>

#include "server/store/match_store.h"
#include "server/store/stat_book.h"
#include "store_fixture.h"

namespace pool::store {
namespace {

using test::Scratch;

}  // namespace

void PrintTo(const PlayerStats& s, std::ostream* os) {
  *os << s.name << ": matches " << s.matches << "/" << s.matches_won << ", racks " << s.racks << "/"
      << s.racks_won << ", strokes " << s.strokes << ", attempts " << s.attempts << ", pots "
      << s.pots << ", breaks " << s.breaks << ", break pots " << s.break_pots << ", break-and-runs "
      << s.break_and_runs << ", fouls " << s.fouls << ", safeties " << s.safeties << ", high run "
      << s.high_run;
}

namespace {

const std::vector<std::uint8_t> kStatsAnn(32, 0xA1), kStatsBen(32, 0xB2);

server::MatchSnapshot nineBallRace(rules::Phase phase = rules::Phase::Open) {
  server::MatchSnapshot m;
  m.id = "srv-1";
  m.number = 1;
  m.name = "Table 1";
  m.started = true;
  m.settings.game = rules::Game::NineBall;
  m.settings.race_to = 2;
  m.game.phase = phase;
  m.seats[0].player = "ann";
  m.seats[0].public_key = kStatsAnn;
  m.seats[1].player = "ben";
  m.seats[1].public_key = kStatsBen;
  return m;
}

/// One stroke of the script: who shoots, whether it breaks or is a declared safety, what fell,
/// whether it fouls, whether the shooter stays at the table, and the rack's winner (-1: none).
struct Stroke {
  int seat = 0;
  bool breaks = false;
  bool safety = false;
  std::vector<int> pocketed = {};
  bool foul = false;
  bool stays = false;
  int wins_rack = -1;
  bool times_out = false;  ///< no stroke: the shot clock ran out (a foul)
};

void storeStroke(MatchStore& s, const Stroke& k, std::uint32_t number, bool match_over,
                 const std::string& match = "srv-1") {
  server::ShotRecord r;
  r.shoots = !k.times_out;
  r.command.seat = k.seat;
  r.command.seq = number;
  r.shot_number = number;
  r.state.phase = k.breaks ? rules::Phase::Break : rules::Phase::Open;
  r.intent.safety = k.safety;
  r.verdict.pocketed = k.pocketed;
  if (k.foul) r.verdict.fouls = {rules::Foul::CueBallPocketed};
  if (k.times_out) r.verdict.fouls = {rules::Foul::ShotClockExpired};
  r.verdict.turn_continues = k.stays;
  r.verdict.game_over = k.wins_rack >= 0;
  r.verdict.winner = k.wins_rack;
  server::MatchSnapshot after = nineBallRace(match_over ? rules::Phase::Over : rules::Phase::Open);
  after.id = match;
  after.number = match == "srv-1" ? 1 : 2;
  after.shot_number = number;
  s.recordShot(r, "scripted", after);
}

TEST(StatBook, AScriptedRaceCountsEachPlayersPotsFoulsBreaksAndRuns) {
  Scratch scratch;
  auto opened = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(opened) << opened.error();
  MatchStore& s = **opened;
  const std::vector<Stroke> script{
      // Rack 1: ann breaks (the 3 and 5 fall) and runs out: 1; 2 and 4; 6, 7, 8 and 9.
      {.seat = 0, .breaks = true, .pocketed = {3, 5}, .stays = true},
      {.seat = 0, .pocketed = {1}, .stays = true},
      {.seat = 0, .pocketed = {2, 4}, .stays = true},
      {.seat = 0, .pocketed = {6, 7, 8, 9}, .wins_rack = 0},
      // Rack 2: ben breaks dry; ann scratches; ben plays safe; ann pots the 1, then misses;
      // ben pots the 2 and 3, then fouls; ann pots the 9: her second rack, the match.
      {.seat = 1, .breaks = true},
      {.seat = 0, .foul = true},
      {.seat = 1, .safety = true},
      {.seat = 0, .pocketed = {1}, .stays = true},
      {.seat = 0},
      {.seat = 1, .pocketed = {2, 3}, .stays = true},
      {.seat = 1, .foul = true},
      {.seat = 0, .pocketed = {9}, .wins_rack = 0},
  };
  for (std::size_t i = 0; i < script.size(); ++i) {
    storeStroke(s, script[i], static_cast<std::uint32_t>(i + 1), i + 1 == script.size());
  }
  const auto ann = statsOf(s.database(), kStatsAnn, rules::Game::NineBall);
  const auto ben = statsOf(s.database(), kStatsBen, rules::Game::NineBall);
  ASSERT_TRUE(ann && ben);
  // ann: 8 strokes, 7 of them attempts (all but the break), potting 1+2+4+1+1 = 9; the break's
  // 2; the first rack a break-and-run; one foul; the best inning 2+1+2+4 = 9 balls.
  PlayerStats want_ann{.key = kStatsAnn,
                       .game = rules::Game::NineBall,
                       .name = "ann",
                       .matches = 1,
                       .matches_won = 1,
                       .racks = 2,
                       .racks_won = 2,
                       .strokes = 8,
                       .attempts = 7,
                       .pots = 9,
                       .breaks = 1,
                       .break_pots = 2,
                       .break_and_runs = 1,
                       .fouls = 1,
                       .safeties = 0,
                       .high_run = 9};
  EXPECT_EQ(*ann, want_ann);
  // ben: 4 strokes: the dry break, the safety, then the 2 and 3 (an attempt) and a foul.
  PlayerStats want_ben{.key = kStatsBen,
                       .game = rules::Game::NineBall,
                       .name = "ben",
                       .matches = 1,
                       .matches_won = 0,
                       .racks = 2,
                       .racks_won = 0,
                       .strokes = 4,
                       .attempts = 2,
                       .pots = 2,
                       .breaks = 1,
                       .break_pots = 0,
                       .break_and_runs = 0,
                       .fouls = 1,
                       .safeties = 1,
                       .high_run = 2};
  EXPECT_EQ(*ben, want_ben);
  // A rematch's first rack: ben breaks and the 9 falls on the break, a break-and-run of one
  // stroke.
  storeStroke(s, {.seat = 1, .breaks = true, .pocketed = {9}, .wins_rack = 1}, 13, false);
  const auto snap = statsOf(s.database(), kStatsBen, rules::Game::NineBall);
  ASSERT_TRUE(snap);
  EXPECT_EQ(snap->break_and_runs, 1);
  EXPECT_EQ(snap->break_pots, 1);
  EXPECT_EQ(snap->racks_won, 1);
  // Per game: nothing in 8-ball; the most recent first.
  EXPECT_FALSE(statsOf(s.database(), kStatsAnn, rules::Game::EightBall));
  const auto recent = recentStats(s.database(), 10);
  ASSERT_EQ(recent.size(), 2u);
  EXPECT_EQ(recentStats(s.database(), 1).size(), 1u);
}

TEST(StatBook, AnInningIsItsMatchsOwnAndAShotClockFoulEndsIt) {
  Scratch scratch;
  auto opened = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(opened) << opened.error();
  MatchStore& s = **opened;
  // ann at two tables at once: her break in the first (2 balls), a pot in the second (1), then
  // the 9 in the first: that inning is 3 balls from her break, a break-and-run; the second's 1.
  storeStroke(s, {.seat = 0, .breaks = true, .pocketed = {3, 5}, .stays = true}, 1, false);
  storeStroke(s, {.seat = 0, .pocketed = {4}, .stays = true}, 1, false, "srv-2");
  storeStroke(s, {.seat = 0, .pocketed = {9}, .wins_rack = 0}, 2, false);
  // In the second the shot clock runs out (a foul, no stroke): her inning there ends; her next
  // pot there begins another.
  storeStroke(s, {.seat = 0, .times_out = true}, 2, false, "srv-2");
  storeStroke(s, {.seat = 0, .pocketed = {6}, .stays = true}, 2, false, "srv-2");
  const auto ann = statsOf(s.database(), kStatsAnn, rules::Game::NineBall);
  ASSERT_TRUE(ann);
  EXPECT_EQ(ann->high_run, 3);  // not 4: the second table's pot is not part of the first's run
  EXPECT_EQ(ann->break_and_runs, 1);
  EXPECT_EQ(ann->strokes, 4);  // the clock's run out is no stroke
  EXPECT_EQ(ann->fouls, 1);
  EXPECT_EQ(ann->pots, 3);
}

TEST(StatBook, PracticeAndHotSeatPlayAreNotCounted) {
  server::MatchSnapshot practice = nineBallRace();
  practice.settings.practice = true;
  server::MatchSnapshot hot_seat = nineBallRace();
  hot_seat.seats[1].public_key = kStatsAnn;
  server::MatchSnapshot unsigned_seat = nineBallRace();
  unsigned_seat.seats[0].public_key.clear();
  EXPECT_TRUE(countsForStats(nineBallRace()));
  for (const auto* m : {&practice, &hot_seat, &unsigned_seat}) EXPECT_FALSE(countsForStats(*m));
  Scratch scratch;
  auto opened = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(opened) << opened.error();
  server::ShotRecord r;
  r.verdict.pocketed = {1};
  (*opened)->recordShot(r, "hot seat", hot_seat);
  EXPECT_TRUE(recentStats((*opened)->database(), 10).empty());
}

}  // namespace
}  // namespace pool::store
