// Two pool-bots play a frame of snooker (a race to one frame) against pool-server --fast over
// loopback DDS, on the snooker table; a spectator follows every shot's frames and the score, and
// the server's stored shots, judged again, give the same winner.
#include <gtest/gtest.h>

#include <cstdio>

#include "rules/snooker.h"
#include "support/client_fixture.h"
#include "support/stored_match_check.h"

namespace pool::client::test {
namespace {

class SnookerMatchTest : public ClientIntegrationTest {};

TEST_F(SnookerMatchTest, TwoBotsPlayAFrameToTheEnd) {
  open(kSnookerFrame, "snooker");
  MatchRecorder recorder(kSnookerFrame);
  ChildProcess& server = startServer({"--fast", "--game", "snooker", "--race", "1", "--rack-seed",
                                      "11", "--db", scratch_->file("pool.db")});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  })) << "the server's match never reached the recorder";
  const std::string match = recorder.firstMatch();
  const LobbyEntry* entry = recorder.client().lobby().find(match);
  ASSERT_NE(entry, nullptr);
  EXPECT_EQ(entry->table, "snooker-12ft");
  EXPECT_EQ(entry->settings.game, rules::Game::Snooker);
  EXPECT_EQ(entry->settings.race_to, 1);
  // The frame's opening: 22 balls, the reds and colours on the table, the breaker in the D.
  const MatchView* first = recorder.latest(match);
  ASSERT_NE(first, nullptr);
  EXPECT_EQ(first->balls.size(), 22u);
  ChildProcess& ann = start("pool-bot",
                            {"--domain", std::to_string(domain_), "--name", "ann", "--think", "0",
                             "--seed", "3", "--timeout", "500"},
                            "ann");
  ChildProcess& ben = start("pool-bot",
                            {"--domain", std::to_string(domain_), "--name", "ben", "--think", "0",
                             "--seed", "4", "--timeout", "500"},
                            "ben");
  const auto begun = std::chrono::steady_clock::now();
  bool saw_in_the_d = false, saw_on_colour = false, saw_foul_points = false;
  ASSERT_TRUE(recorder.pump(500s, [&] {
    if (const MatchView* v = recorder.latest(match)) {
      saw_in_the_d |= v->ball_in_hand == rules::BallInHand::InTheD;
      saw_on_colour |= v->ball_on == rules::kOnColour;
      saw_foul_points |= v->last_verdict.find(" away") != std::string::npos;
    }
    return !ann.running() && !ben.running();
  })) << logs();
  const double seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - begun).count();
  EXPECT_EQ(ann.waitExit(1s), 0) << ann.err();
  EXPECT_EQ(ben.waitExit(1s), 0) << ben.err();
  recorder.pump(5s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->phase == MatchPhase::Over;
  });
  const MatchView* last = recorder.latest(match);
  ASSERT_NE(last, nullptr);
  ASSERT_EQ(last->phase, MatchPhase::Over);
  ASSERT_TRUE(last->winner == 0 || last->winner == 1);
  const auto w = static_cast<std::size_t>(last->winner);
  EXPECT_EQ(last->seats[w].racks_won, 1);
  EXPECT_TRUE(saw_in_the_d);  // the break-off is played from the D
  EXPECT_TRUE(saw_on_colour) << "no red was ever potted";
  if (last->end == rules::GameEnd::FrameOver) {
    // The frame ran to its last ball: every ball but the black is down (a foul on the last
    // black ends the frame too) and the winner has more points.
    EXPECT_GT(last->seats[w].points, last->seats[1 - w].points);
    for (const auto& b : last->balls) {
      if (b.id != 0 && b.id != 21) {
        EXPECT_FALSE(physics::onTable(b.state)) << "ball " << b.id << " still up";
      }
    }
  } else {
    EXPECT_EQ(last->end, rules::GameEnd::ThreeMisses);
  }
  // The most a frame can hold without fouls is 147; fouls add to it.
  const int total = last->seats[0].points + last->seats[1].points;
  EXPECT_GT(total, 0);
  if (!saw_foul_points) {
    EXPECT_LE(total, 147);
  }
  // The spectator saw every shot in motion; the store agrees.
  expectStoredMatchAgrees(recorder, server, scratch_->file("pool.db"), match, "snooker-12ft",
                          *last);
  std::printf(
      "snooker, one frame, match %s: %u shots in %.1f s, %d-%d (%s), high breaks %d and %d\n",
      match.c_str(), last->shot_number, seconds, last->seats[0].points, last->seats[1].points,
      rules::toString(last->end), last->seats[0].high_run, last->seats[1].high_run);
}

}  // namespace
}  // namespace pool::client::test
