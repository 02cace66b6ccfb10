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
#include "support/child_process.h"
#include "support/match_recorder.h"

namespace pool::client::test {

/// Checks that `recorder` saw frames of every shot of `last`, stops `server` (SIGTERM), and judges
/// `match`'s stored shots again from the database `db` on `table`: no problem, as many shots and
/// the same winner as `last`, and the match stored on that table.
inline void expectStoredMatchAgrees(MatchRecorder& recorder, ChildProcess& server,
                                    const std::string& db, const std::string& match,
                                    const std::string& table, const MatchView& last) {
  using namespace std::chrono_literals;
  for (std::uint32_t shot = 1; shot <= last.shot_number; ++shot) {
    EXPECT_FALSE(recorder.frames(match, shot).empty()) << "no frame of shot " << shot;
  }
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
}

}  // namespace pool::client::test
