// Ratings in a real SQLite file: a decided match between two keys is rated once, with the
// Glicko-2 update of both players (Glickman 2013, as rating::afterMatch computes it), in the
// transaction that stores the match; practice, hot-seat and undecided matches are not rated; a
// rematch is rated again from the ratings the first match left.
#include <gtest/gtest.h>

#include "server/store/match_store.h"
#include "server/store/rating_book.h"
#include "store_fixture.h"

namespace pool::store {
namespace {

using test::Scratch;

const std::vector<std::uint8_t> kAnn(32, 0xA1), kBen(32, 0xB2);

server::MatchSnapshot decided(int winner, std::uint32_t rack, std::uint32_t shot) {
  server::MatchSnapshot m;
  m.id = "srv-1";
  m.number = 1;
  m.name = "Table 1";
  m.started = true;
  m.rack = rack;
  m.shot_number = shot;
  m.settings.game = rules::Game::NineBall;
  m.game.phase = rules::Phase::Over;
  m.game.winner = winner;
  m.seats[0].player = "ann";
  m.seats[0].public_key = kAnn;
  m.seats[1].player = "ben";
  m.seats[1].public_key = kBen;
  return m;
}

TEST(RatingBook, ADecidedMatchRatesBothPlayersOnceWithGlicko2) {
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  (*store)->saveMatches("srv", 1, {decided(1, 1, 12)});
  // Two new players (1500, 350, 0.06): the expected ratings are afterMatch's, computed here.
  const auto [won, lost] = rating::afterMatch(rating::Rating{}, rating::Rating{});
  Database& db = (*store)->database();
  const rating::Rating ben = ratingOf(db, kBen, rules::Game::NineBall);
  const rating::Rating ann = ratingOf(db, kAnn, rules::Game::NineBall);
  EXPECT_DOUBLE_EQ(ben.rating, won.rating);
  EXPECT_DOUBLE_EQ(ben.deviation, won.deviation);
  EXPECT_DOUBLE_EQ(ann.rating, lost.rating);
  EXPECT_GT(ben.rating, 1500.0);
  EXPECT_LT(ann.rating, 1500.0);
  // Per game: ann's 8-ball rating is untouched.
  EXPECT_DOUBLE_EQ(ratingOf(db, kAnn, rules::Game::EightBall).rating, 1500.0);
  // The result, with the ratings before and after.
  auto results = ratedResults(db, "srv-1");
  ASSERT_EQ(results.size(), 1u);
  EXPECT_EQ(results[0].winner_key, kBen);
  EXPECT_EQ(results[0].loser_key, kAnn);
  EXPECT_DOUBLE_EQ(results[0].winner_before, 1500.0);
  EXPECT_DOUBLE_EQ(results[0].winner_after, won.rating);
  EXPECT_DOUBLE_EQ(results[0].loser_after, lost.rating);
  // Saved again (the server saves every match often): not rated twice.
  (*store)->saveMatches("srv", 1, {decided(1, 1, 12)});
  EXPECT_EQ(ratedResults(db, "srv-1").size(), 1u);
  EXPECT_DOUBLE_EQ(ratingOf(db, kBen, rules::Game::NineBall).rating, won.rating);
  EXPECT_EQ(db.integer("SELECT matches FROM ratings WHERE game = 9 LIMIT 1"), 1);
  // A rematch won by ann: rated from the ratings the first match left.
  (*store)->saveMatches("srv", 1, {decided(0, 2, 20)});
  const auto [ann_after, ben_after] = rating::afterMatch(lost, won);
  EXPECT_DOUBLE_EQ(ratingOf(db, kAnn, rules::Game::NineBall).rating, ann_after.rating);
  EXPECT_DOUBLE_EQ(ratingOf(db, kBen, rules::Game::NineBall).rating, ben_after.rating);
  EXPECT_EQ(ratedResults(db, "srv-1").size(), 2u);
}

TEST(RatingBook, PracticeHotSeatUnsignedAndUndecidedMatchesAreNotRated) {
  server::MatchSnapshot practice = decided(0, 1, 5);
  practice.settings.practice = true;
  server::MatchSnapshot hot_seat = decided(0, 1, 5);
  hot_seat.seats[1].public_key = kAnn;
  server::MatchSnapshot unsigned_seat = decided(0, 1, 5);
  unsigned_seat.seats[1].public_key.clear();
  server::MatchSnapshot in_play = decided(0, 1, 5);
  in_play.game.phase = rules::Phase::Open;
  in_play.game.winner = -1;
  EXPECT_TRUE(isRated(decided(0, 1, 5)));
  for (const auto* m : {&practice, &hot_seat, &unsigned_seat, &in_play}) EXPECT_FALSE(isRated(*m));
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  (*store)->saveMatches("srv", 1, {hot_seat});
  EXPECT_TRUE(ratedResults((*store)->database(), "srv-1").empty());
  EXPECT_EQ((*store)->database().integer("SELECT COUNT(*) FROM ratings"), 0);
}

TEST(RatingBook, TheRatingAndTheMatchAreOneTransaction) {
  // A write that fails after the ratings rolls both back: a trigger made by hand refuses the
  // result's row after the ratings' rows went in, inside saveMatches' transaction.
  Scratch scratch;
  auto store = MatchStore::open(scratch.file("pool.db"));
  ASSERT_TRUE(store) << store.error();
  Database& db = (*store)->database();
  db.exec(
      "CREATE TRIGGER refuse BEFORE INSERT ON rated_results BEGIN SELECT RAISE(ABORT, 'no'); END");
  EXPECT_THROW((*store)->saveMatches("srv", 1, {decided(1, 1, 12)}), StoreError);
  EXPECT_EQ(db.integer("SELECT COUNT(*) FROM ratings"), 0);
  EXPECT_EQ(db.integer("SELECT COUNT(*) FROM matches"), 0);
}

}  // namespace
}  // namespace pool::store
