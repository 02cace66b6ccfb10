// A stored shot asked of its server and replayed in the lobby's stead: the shot asked (the last
// one found through the answers), asked again while unanswered, walked within 1..shots, and its
// balls on the caller's clock from the layout at the strike to the layout at rest, held.
#include "client/app/stored_replay.h"

#include <gtest/gtest.h>

namespace pool::app::test {
namespace {

constexpr double kStoredR = 0.028575;

physics::Ball storedBallAt(int id, double x, double y) {
  physics::Ball b;
  b.id = id;
  b.pos = physics::Vec3(x, y, kStoredR);
  return b;
}

/// Shot `n` of `shots` of srv-1 as the server answers request `request`: the cue ball rolls from
/// (0, 0) to rest at (0.5, 0) in one second; the 1 stays at (1, 0.3).
protocol::HistoryShot storedFound(std::uint32_t request, std::uint32_t n, std::uint32_t shots) {
  protocol::HistoryShot s;
  s.request = request;
  s.match = "srv-1";
  s.found = true;
  s.shot_number = n;
  s.shots = shots;
  s.table = "wpa-9ft";
  s.players = {"Ada", "Bo"};
  s.before = {storedBallAt(0, 0.0, 0.0), storedBallAt(1, 1.0, 0.3)};
  physics::Event strike;
  strike.type = physics::EventType::Strike;
  strike.pos = s.before[0].pos;
  physics::Event rest;
  rest.t = 1.0;
  rest.type = physics::EventType::RollToRest;
  rest.pos = physics::Vec3(0.5, 0.0, kStoredR);
  s.events = {strike, rest};
  s.after = {storedBallAt(0, 0.5, 0.0), storedBallAt(1, 1.0, 0.3)};
  s.verdict_text = "legal; open, seat 0 to shoot";
  return s;
}

protocol::HistoryShot storedNotFound(std::uint32_t request, std::uint32_t shots,
                                     std::string error) {
  protocol::HistoryShot s;
  s.request = request;
  s.match = "srv-1";
  s.shots = shots;
  s.error = std::move(error);
  return s;
}

/// Frames at 0, 0.1, 0.2 s and the last at 0.25 s, each with the cue ball at x = 10 t.
std::vector<ReplayFrame> storedFramesAt() {
  std::vector<ReplayFrame> frames;
  for (const double t : {0.0, 0.1, 0.2, 0.25})
    frames.push_back({t, {storedBallAt(0, 10 * t, 0.0)}});
  return frames;
}

TEST(StoredReplayFrame, TheLastFrameAtOrBeforeTheTimeTheFirstBeforeTheStrikeTheLastAfterTheEnd) {
  const auto frames = storedFramesAt();
  EXPECT_EQ(frameAt({}, 1.0), nullptr);
  EXPECT_EQ(frameAt(frames, -0.4)->t, 0.0);
  EXPECT_EQ(frameAt(frames, 0.0)->t, 0.0);
  EXPECT_EQ(frameAt(frames, 0.05)->t, 0.0);
  EXPECT_EQ(frameAt(frames, 0.1)->t, 0.1);
  EXPECT_EQ(frameAt(frames, 0.19)->t, 0.1);
  EXPECT_EQ(frameAt(frames, 0.24)->t, 0.2);
  EXPECT_EQ(frameAt(frames, 0.25)->t, 0.25);
  EXPECT_EQ(frameAt(frames, 7.0)->t, 0.25);
}

TEST(StoredReplayWalk, StepsStayWithinOneAndTheMatchsShots) {
  EXPECT_EQ(steppedShot(3, -1, 9), 2u);
  EXPECT_EQ(steppedShot(3, 1, 9), 4u);
  EXPECT_EQ(steppedShot(1, -1, 9), 1u);
  EXPECT_EQ(steppedShot(9, 1, 9), 9u);
  EXPECT_EQ(steppedShot(500, -1, 9), 9u);  // from a shot the match never had: its last
  EXPECT_EQ(steppedShot(4, 1, 0), 1u);     // none told yet
}

TEST(StoredReplayTitle, TheShotOfTheMatchItsShooterAndTheVerdictWithNames) {
  protocol::HistoryShot s = storedFound(1, 3, 9);
  s.seat = 1;
  s.verdict_text = "legal; pocketed 4; open, seat 0 to shoot";
  EXPECT_EQ(storedShotTitle(s),
            "Replay of srv-1, shot 3 of 9: Bo - legal; pocketed 4; open, Ada to shoot");
  s.players = {"", ""};
  s.seat = 0;
  s.verdict_text.clear();
  EXPECT_EQ(storedShotTitle(s), "Replay of srv-1, shot 3 of 9: Player 1");
}

TEST(StoredReplay, AsksTheShotAgainWhileUnansweredThenShowsItsAnswer) {
  StoredReplay r;
  EXPECT_FALSE(r.isOpen());
  EXPECT_FALSE(r.due(0.0));
  r.open("srv-1", 4);
  EXPECT_TRUE(r.isOpen());
  EXPECT_TRUE(r.waiting());
  EXPECT_EQ(r.due(0.0), 4u);
  r.asked(10, 0.0);
  EXPECT_FALSE(r.due(0.5));
  EXPECT_EQ(r.due(1.0), 4u);  // no answer within a second: again
  r.asked(11, 1.0);
  // Answers to requests not ours, or about another match, change nothing.
  EXPECT_FALSE(r.take(storedFound(99, 4, 9), 1.1));
  auto other = storedFound(10, 4, 9);
  other.match = "srv-2";
  EXPECT_FALSE(r.take(other, 1.1));
  EXPECT_EQ(r.shown(), nullptr);
  // The first ask's answer is as good as the second's.
  EXPECT_TRUE(r.take(storedFound(10, 4, 9), 1.2));
  ASSERT_NE(r.shown(), nullptr);
  EXPECT_EQ(r.shown()->shot_number, 4u);
  EXPECT_EQ(r.shots(), 9u);
  EXPECT_FALSE(r.waiting());
  EXPECT_FALSE(r.due(5.0));
  EXPECT_FALSE(r.take(storedFound(11, 4, 9), 1.3)) << "the repeated ask's answer is not a new shot";
  r.close();
  EXPECT_FALSE(r.isOpen());
  EXPECT_EQ(r.shown(), nullptr);
}

TEST(StoredReplay, GivesUpAfterItsAsksWentUnanswered) {
  StoredReplay r;
  r.open("srv-1", 2);
  double now = 0.0;
  int asks = 0;
  for (; now < 60.0; now += 0.25) {
    if (r.due(now)) r.asked(static_cast<std::uint32_t>(++asks), now);
  }
  EXPECT_EQ(asks, StoredReplay::kAsksPerShot);
  EXPECT_EQ(r.problem(), "no answer from the server of srv-1 for shot 2");
}

TEST(StoredReplay, TheLastShotIsFoundThroughTheFirstAnswer) {
  StoredReplay r;
  r.open("srv-1");  // no count known: shot 1 first
  EXPECT_EQ(r.wanted(), 1u);
  EXPECT_EQ(r.due(0.0), 1u);
  r.asked(1, 0.0);
  EXPECT_TRUE(r.take(storedFound(1, 1, 9), 0.1));
  EXPECT_EQ(r.shown(), nullptr) << "shot 1 is not the last of nine";
  EXPECT_EQ(r.due(0.1), 9u);
  r.asked(2, 0.1);
  EXPECT_TRUE(r.take(storedFound(2, 9, 9), 0.2));
  ASSERT_NE(r.shown(), nullptr);
  EXPECT_EQ(r.shown()->shot_number, 9u);
}

TEST(StoredReplay, TheLobbysCountIsAskedFirstAndAShotStillPlayedGivesTheOneBefore) {
  StoredReplay r;
  r.open("srv-1", 0, 12);
  EXPECT_EQ(r.due(0.0), 12u);
  r.asked(1, 0.0);
  // The match has only ten stored: the tenth then.
  EXPECT_TRUE(r.take(storedNotFound(1, 10, "match srv-1 has 10 shots: no shot 12"), 0.1));
  EXPECT_EQ(r.due(0.1), 10u);
  r.asked(2, 0.1);
  EXPECT_TRUE(r.take(storedNotFound(2, 10, "shot 10 of srv-1 is still being played"), 0.2));
  EXPECT_EQ(r.due(0.2), 9u);
  r.asked(3, 0.2);
  // Shot 9 of 10 is shown: the tenth is not asked again.
  EXPECT_TRUE(r.take(storedFound(3, 9, 10), 0.3));
  ASSERT_NE(r.shown(), nullptr);
  EXPECT_EQ(r.shown()->shot_number, 9u);
  EXPECT_FALSE(r.due(5.0));
  EXPECT_TRUE(r.problem().empty());
}

TEST(StoredReplay, AShotTheMatchNeverHadIsSaidInTheServersLine) {
  StoredReplay r;
  r.open("srv-1", 500);
  r.due(0.0);
  r.asked(1, 0.0);
  EXPECT_TRUE(r.take(storedNotFound(1, 9, "match srv-1 has 9 shots: no shot 500"), 0.1));
  EXPECT_EQ(r.problem(), "match srv-1 has 9 shots: no shot 500");
  EXPECT_EQ(r.shown(), nullptr);
  EXPECT_FALSE(r.due(10.0)) << "not asked again";
  // Previous goes to the match's last.
  EXPECT_TRUE(r.previous());
  EXPECT_EQ(r.due(10.0), 9u);
  EXPECT_TRUE(r.problem().empty());
}

TEST(StoredReplay, PreviousAndNextWalkWithinTheMatchsShots) {
  StoredReplay r;
  r.open("srv-1", 2);
  r.due(0.0);
  r.asked(1, 0.0);
  r.take(storedFound(1, 2, 3), 0.0);
  EXPECT_TRUE(r.hasPrevious());
  EXPECT_TRUE(r.hasNext());
  EXPECT_TRUE(r.previous());
  EXPECT_EQ(r.wanted(), 1u);
  EXPECT_TRUE(r.waiting());
  EXPECT_EQ(r.shown()->shot_number, 2u) << "shot 2 shows until shot 1 arrives";
  EXPECT_FALSE(r.previous()) << "no shot before the first";
  EXPECT_EQ(r.due(0.1), 1u);
  r.asked(2, 0.1);
  EXPECT_FALSE(r.take(storedFound(1, 2, 3), 0.2)) << "an answer for a shot no longer wanted";
  EXPECT_TRUE(r.take(storedFound(2, 1, 3), 0.2));
  EXPECT_EQ(r.shown()->shot_number, 1u);
  EXPECT_TRUE(r.next());
  EXPECT_TRUE(r.next());
  EXPECT_EQ(r.wanted(), 3u);
  EXPECT_FALSE(r.next()) << "no shot after the last";
  EXPECT_EQ(r.wanted(), 3u);
}

TEST(StoredReplay, PlaysFromTheLayoutAtTheStrikeToTheLayoutAtRestAndHoldsIt) {
  StoredReplay r;
  r.open("srv-1", 4);
  r.due(0.0);
  r.asked(1, 0.0);
  EXPECT_FALSE(r.balls(0.0)) << "nothing before the answer";
  const double answered = 100.0;
  const protocol::HistoryShot shot = storedFound(1, 4, 9);
  ASSERT_TRUE(r.take(shot, answered));
  const double strike = answered + StoredReplay::kLead;
  // Before the strike: the layout at the strike.
  auto balls = r.balls(answered);
  ASSERT_TRUE(balls);
  ASSERT_EQ(balls->size(), 2u);
  EXPECT_EQ((*balls)[0].pos, physics::Vec3(0.0, 0.0, kStoredR));
  EXPECT_LT(r.time(answered), 0.0);
  EXPECT_FALSE(r.atRest(answered));
  // Half-way through the second it rolls: the cue ball between its two places, moving on; the
  // 1 where it was.
  const auto mid = r.balls(strike + 0.5);
  const auto later = r.balls(strike + 0.75);
  ASSERT_TRUE(mid && later);
  EXPECT_GT((*mid)[0].pos.x(), 0.0);
  EXPECT_LT((*mid)[0].pos.x(), 0.5);
  EXPECT_GT((*later)[0].pos.x(), (*mid)[0].pos.x());
  EXPECT_EQ((*mid)[0].pos.y(), 0.0);
  EXPECT_EQ((*mid)[1].pos, physics::Vec3(1.0, 0.3, kStoredR));
  EXPECT_FALSE(r.atRest(strike + 0.5));
  // From the last event on: the layout at rest, exactly, held.
  for (const double t : {1.0, 1.5, 60.0}) {
    const auto end = r.balls(strike + t);
    ASSERT_TRUE(end);
    EXPECT_EQ((*end)[0].pos, physics::Vec3(0.5, 0.0, kStoredR)) << t;
    EXPECT_EQ((*end)[1].pos, physics::Vec3(1.0, 0.3, kStoredR)) << t;
    EXPECT_TRUE(r.atRest(strike + t)) << t;
  }
  // Play again: from the strike anew.
  r.again(strike + 60.0);
  EXPECT_EQ((*r.balls(strike + 60.0))[0].pos, physics::Vec3(0.0, 0.0, kStoredR));
  EXPECT_FALSE(r.atRest(strike + 60.0 + StoredReplay::kLead + 0.5));
}

}  // namespace
}  // namespace pool::app::test
