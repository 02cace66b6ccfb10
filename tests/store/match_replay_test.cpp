// MatchReplay: a stored break played again on a fresh match with the same rack seed matches its
// stored table and events; a stored log that says otherwise is reported.
#include <gtest/gtest.h>

#include "server/match/match_replay.h"
#include "stored_break.h"

namespace pool::store::test {
namespace {

/// Replays `commands` of the stored match `stored` to their end; returns the replay's findings.
std::vector<std::string> replayAll(const server::MatchSnapshot& stored,
                                   std::vector<server::ShotRecord> commands,
                                   std::uint32_t& replayed) {
  server::Match target("rep-1", "Replay", server::test::runner(), {}, stored.rack_seed,
                       stored.rack_generator);
  server::MatchReplay replay(stored, std::move(commands), target, {0xAAAA, 0xBBBB}, 0.5);
  for (double now = 0.0; !replay.done() && now < 100.0; now += 0.25) {
    replay.step(now);
    server::test::finishNow(target);
  }
  EXPECT_TRUE(replay.done());
  replayed = replay.replayed();
  return replay.differences();
}

TEST(MatchReplayTest, AStoredBreakReplaysToTheSameTableAndEvents) {
  BrokenMatch b;
  ASSERT_TRUE(b.answer.record);
  server::MatchSnapshot stored = b.match->snapshot();
  stored.rack_seed = 42;  // seatedMatch's seed
  std::uint32_t replayed = 0;
  const auto differences = replayAll(stored, {*b.answer.record}, replayed);
  EXPECT_EQ(replayed, 1u);
  EXPECT_TRUE(differences.empty()) << differences.front();
}

TEST(MatchReplayTest, AStoredLogThatDiffersIsReported) {
  BrokenMatch b;
  ASSERT_TRUE(b.answer.record);
  server::MatchSnapshot stored = b.match->snapshot();
  stored.rack_seed = 42;
  server::ShotRecord altered = *b.answer.record;
  altered.events.back().t += 1e-9;
  std::uint32_t replayed = 0;
  auto differences = replayAll(stored, {altered}, replayed);
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_NE(differences[0].find("another story"), std::string::npos) << differences[0];

  // Another rack seed lays out another table.
  stored.rack_seed = 43;
  differences = replayAll(stored, {*b.answer.record}, replayed);
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_NE(differences[0].find("another table"), std::string::npos) << differences[0];
}

// The rack's gaps are part of what is stored: the same seed racked by the other generator is
// another table (a frozen triangle instead of the hand rack the break was played on).
TEST(MatchReplayTest, TheRackGeneratorIsPartOfTheStoredTable) {
  BrokenMatch b;
  ASSERT_TRUE(b.answer.record);
  server::MatchSnapshot stored = b.match->snapshot();
  EXPECT_EQ(stored.rack_generator, table::kCurrentRackGenerator);
  stored.rack_seed = 42;
  stored.rack_generator = table::RackGenerator::Frozen;
  std::uint32_t replayed = 0;
  const auto differences = replayAll(stored, {*b.answer.record}, replayed);
  ASSERT_EQ(differences.size(), 1u);
  EXPECT_NE(differences[0].find("another table"), std::string::npos) << differences[0];
}

}  // namespace
}  // namespace pool::store::test
