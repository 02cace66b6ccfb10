// After a real match: every shot was seen in motion, and the server's store, judged again once the
// server stops, gives the same shots and winner.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <csignal>
#include <string>

#include "game/loaded_table.h"
#include "server/store/match_audit.h"
#include "server/store/match_store.h"
#include "server/store/rating_book.h"
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
}

}  // namespace pool::client::test
