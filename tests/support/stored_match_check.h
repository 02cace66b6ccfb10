// After a real match: every shot was seen in motion, and the server's store, judged again once the
// server stops, gives the same shots and winner.
#pragma once

#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <cmath>
#include <csignal>
#include <optional>
#include <string>

#include "game/loaded_table.h"
#include "server/store/match_audit.h"
#include "server/store/match_store.h"
#include "server/store/rating_book.h"
#include "server/store/stat_book.h"
#include "support/child_process.h"
#include "support/match_recorder.h"

namespace pool::client::test {

/// Checks that `recorder` saw frames of the shots of `last` (all but one in twenty at most, the
/// last among them), stops `server` (SIGTERM), and judges `match`'s stored shots again from the
/// database `db` on `table`: no problem, as many shots and the same winner as `last`, and the match
/// stored on that table; the two players (bots, each with a key of its own) rated once, the winner
/// up and the loser down, in the store and the lobby.
inline void expectStoredMatchAgrees(MatchRecorder& recorder, ChildProcess& server,
                                    const std::string& db, const std::string& match,
                                    const std::string& table, const MatchView& last) {
  using namespace std::chrono_literals;
  // Frames are best-effort, keep-last 1 (qos_profiles.h: a lost frame is replaced by the next
  // one), so a loaded machine can lose every frame of a very short stroke: of a long match, up to
  // one shot in twenty may go unseen, never the last.
  std::string unseen;
  std::uint32_t missing = 0;
  for (std::uint32_t shot = 1; shot <= last.shot_number; ++shot) {
    if (!recorder.frames(match, shot).empty()) continue;
    ++missing;
    unseen += " " + std::to_string(shot);
  }
  EXPECT_LE(20 * missing, last.shot_number) << "no frame of shots" << unseen;
  EXPECT_FALSE(recorder.frames(match, last.shot_number).empty()) << "no frame of the last shot";
  // The lobby shows the players' new ratings: the winner above a new player's 1500, the loser
  // below.
  const auto w = static_cast<std::size_t>(last.winner);
  const bool shown = recorder.pump(10s, [&] {
    const LobbyEntry* e = recorder.client().lobby().find(match);
    return e && e->ratings[w] > 1500 && e->ratings[1 - w] > 0 && e->ratings[1 - w] < 1500;
  });
  EXPECT_TRUE(shown) << "the lobby never showed the players' ratings";
  // Each player's record (PlayerStats) reaches a client once the last stroke is seen through:
  // one match each, won by the winner.
  std::array<std::optional<protocol::PlayerStats>, 2> records;
  const bool published = recorder.pump(10s, [&] {
    for (std::size_t s = 0; s < 2; ++s) {
      records[s].reset();
      for (const auto* r : recorder.client().players().named(last.seats[s].name)) {
        if (r->game == last.settings.game) records[s] = *r;
      }
    }
    return records[0] && records[1] && records[w]->matches == 1 && records[w]->matches_won == 1 &&
           records[1 - w]->matches == 1 && records[1 - w]->matches_won == 0;
  });
  EXPECT_TRUE(published) << "the players' records never showed the match";
  server.kill(SIGTERM);
  ASSERT_TRUE(server.waitExit(20s)) << "the server did not stop";
  auto store = store::MatchStore::open(db);
  ASSERT_TRUE(store) << store.error();
  EXPECT_EQ((*store)->tableOf(match), table);
  auto kit = game::loadSharedTable(table);
  ASSERT_TRUE(kit) << kit.error();
  const store::Audit audit = store::auditMatch(**store, match, **kit);
  for (const auto& problem : audit.problems) ADD_FAILURE() << match << ": " << problem;
  EXPECT_EQ(audit.shots, last.shot_number);
  EXPECT_EQ(audit.winner, last.winner);
  const auto rated = store::ratedResults((*store)->database(), match);
  ASSERT_EQ(rated.size(), 1u) << "the decided match was not rated once";
  EXPECT_GT(rated[0].winner_after, rated[0].winner_before);
  EXPECT_LT(rated[0].loser_after, rated[0].loser_before);
  if (!published) return;
  // The records published are the store's, with its rating; the strokes they count are the
  // stored strokes.
  int strokes = 0;
  for (const auto& stored : (*store)->shots(match)) strokes += stored.record.shoots ? 1 : 0;
  EXPECT_EQ(records[0]->strokes + records[1]->strokes, strokes);
  for (const auto& record : records) {
    auto kept = store::statsOf((*store)->database(), record->key, record->game);
    ASSERT_TRUE(kept) << record->name << " has no statistics in the store";
    const double rating = store::ratingOf((*store)->database(), record->key, record->game).rating;
    EXPECT_EQ(record->rating, static_cast<int>(std::lround(rating))) << record->name;
    kept->server = record->server;
    kept->rating = record->rating;
    kept->rating_deviation = record->rating_deviation;
    EXPECT_EQ(*kept, *record) << record->name;
  }
}

}  // namespace pool::client::test
