// A shot clock of 5 s against pool-server --fast: a bot told to wait past it loses its turn, with
// the cue ball in hand to its opponent; a bot that is not told to wait shoots within it.
#include <gtest/gtest.h>

#include <algorithm>

#include "support/client_fixture.h"

namespace pool::client::test {
namespace {

class ShotClockTest : public ClientIntegrationTest {};

bool ranOut(const ShotReport& r) {
  return r.final() &&
         std::find(r.fouls.begin(), r.fouls.end(), rules::Foul::ShotClockExpired) != r.fouls.end();
}

TEST_F(ShotClockTest, ABotThatWaitsLosesItsTurnWithBallInHandToTheOpponent) {
  open(kShotClock, "shot-clock");
  MatchRecorder recorder(kShotClock);
  // A race to 3 where the winner breaks: however the first rack goes, Bob's first turn is not a
  // break (a time-out on a break hands the break over instead).
  startServer({"--fast", "--game", "9", "--shot-clock", "5", "--race", "3", "--breaks", "winner"});
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const std::string m = recorder.firstMatch();
    return !m.empty() && recorder.latest(m) != nullptr;
  })) << "the server's match never reached the recorder";
  const std::string match = recorder.firstMatch();
  EXPECT_DOUBLE_EQ(recorder.latest(match)->settings.shot_clock, 5.0);

  // Alice sits first (seat 0, she breaks) and shoots at once; Bob thinks 60 s on every turn and
  // is told to ignore the clock.
  ChildProcess& alice = startBot("alice", 11);
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->seats[0].name == "alice";
  })) << logs();
  startBot("bob", 22, {"--think", "60", "--ignore-shot-clock"});

  // Bob's first turn runs out: the server judges it, a foul, Alice to shoot with ball in hand.
  const ShotReport* expiry = nullptr;
  ASSERT_TRUE(recorder.pump(120s, [&] {
    for (const auto& r : recorder.reports()) {
      if (r.match == match && ranOut(r)) expiry = &r;
    }
    return expiry != nullptr;
  })) << logs();
  const MatchView* state = recorder.latest(match);
  ASSERT_NE(state, nullptr);
  const int bob = seatOf(*state, "bob");
  ASSERT_EQ(bob, 1);
  EXPECT_EQ(expiry->seat, bob);
  EXPECT_TRUE(expiry->accepted);
  EXPECT_TRUE(expiry->events.empty());  // no stroke was played
  EXPECT_EQ(expiry->next_shooter, 0);
  EXPECT_EQ(expiry->ball_in_hand, rules::BallInHand::Anywhere);
  EXPECT_FALSE(expiry->game_over);

  // The extension came first: Bob had 5 s, then 5 s more, before the foul; the state shows it
  // used up and Alice's turn with the cue ball in hand.
  ASSERT_TRUE(recorder.pump(20s, [&] {
    const MatchView* v = recorder.latest(match);
    return v && v->shooter == 0 && v->ball_in_hand == rules::BallInHand::Anywhere &&
           v->seats[1].extensions_left == 0;
  })) << logs();
  // Alice, who was not told to wait, never ran out of time on her turns.
  for (const auto& r : recorder.reports()) {
    if (r.match == match && ranOut(r)) {
      EXPECT_EQ(r.seat, bob) << r.verdict_text;
    }
  }
  EXPECT_TRUE(alice.running());
}

}  // namespace
}  // namespace pool::client::test
