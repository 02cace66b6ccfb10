// Match settings on the server: the opener chooses the game, a race goes on rack after rack, and
// the shot clock runs on the server's time (extension, foul, stalls and the shooter's view).
#include <gtest/gtest.h>

#include "match_fixture.h"
#include "server/match/match.h"
#include "server/match/match_replay.h"

namespace pool::server::test {
namespace {

protocol::MatchSettings nineBallRace(int race, double clock = 0.0) {
  protocol::MatchSettings s;
  s.game = rules::Game::NineBall;
  s.race_to = race;
  s.breaks = protocol::BreakOrder::Winner;
  s.shot_clock = clock;
  return s;
}

int onTable(const Match& m) {
  int n = 0;
  for (const auto& b : m.balls()) n += physics::onTable(b.state) ? 1 : 0;
  return n;
}

TEST(MatchSettings, TheFirstPlayerAtTheTableChoosesTheGame) {
  Match m("srv-1", "Table 1", runner(), pacedOptions(), 42);
  EXPECT_EQ(m.settings().game, rules::Game::EightBall);
  EXPECT_EQ(onTable(m), 16);
  ASSERT_TRUE(m.takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a"), nineBallRace(3)).accepted());
  EXPECT_EQ(m.settings(), nineBallRace(3));
  EXPECT_EQ(onTable(m), 10);  // a 9-ball diamond and the cue ball
  // The second player's wishes change nothing.
  protocol::MatchSettings other;
  other.game = rules::Game::TenBall;
  ASSERT_TRUE(m.takeSeat(1, "Bob", "b", kToken1, publicKeyOf("b"), other).accepted());
  EXPECT_EQ(m.settings(), nineBallRace(3));
  EXPECT_EQ(m.phase(), MatchPhase::Break);
  EXPECT_EQ(m.rules().game, rules::Game::NineBall);
}

TEST(MatchSettings, SettingsAreCheckedAndSigned) {
  EXPECT_TRUE(protocol::checkSettings(nineBallRace(3, 35.0)).ok());
  EXPECT_FALSE(protocol::checkSettings(nineBallRace(0)).ok());
  EXPECT_FALSE(protocol::checkSettings(nineBallRace(16)).ok());
  EXPECT_FALSE(protocol::checkSettings(nineBallRace(3, 4.0)).ok());
  EXPECT_FALSE(protocol::checkSettings(nineBallRace(3, std::nan(""))).ok());
  // A seat request's signature covers its settings: changed in flight, it no longer verifies.
  protocol::SeatRequest r = seatRequest(protocol::JoinAction::Seat, "a", 0, 0, 1);
  r.settings = nineBallRace(3);
  protocol::signSeatRequest(r, keyOf("a"));
  EXPECT_EQ(protocol::verifySeatRequest(r, publicKeyOf("a")), protocol::SignatureCheck::Valid);
  r.settings->race_to = 9;
  EXPECT_EQ(protocol::verifySeatRequest(r, publicKeyOf("a")),
            protocol::SignatureCheck::BadSignature);
}

TEST(MatchSettings, RegistryRefusesBadSettingsAndChangesNothing) {
  RegistryOptions options;
  options.server_id = "srv";
  options.protocol_version = protocol::kProtocolVersion;
  MatchRegistry registry(options, nineFoot());
  Match* table = registry.open();
  ASSERT_NE(table, nullptr);
  protocol::SeatRequest r = seatRequest(protocol::JoinAction::Seat, "a", 0, 0, 1);
  r.match = table->id();
  r.name = "Ada";
  r.settings = nineBallRace(0);
  protocol::signSeatRequest(r, keyOf("a"));
  const JoinAnswer refused = registry.join(r);
  EXPECT_EQ(refused.outcome, JoinOutcome::NotAllowed);
  EXPECT_NE(refused.reason.find("race"), std::string::npos) << refused.reason;
  EXPECT_FALSE(table->seats()[0].taken());
  EXPECT_EQ(table->settings().game, rules::Game::EightBall);
  r.settings = nineBallRace(2);
  r.seq = 2;
  protocol::signSeatRequest(r, keyOf("a"));
  EXPECT_TRUE(registry.join(r).accepted());
  EXPECT_EQ(table->settings(), nineBallRace(2));
}

// Seat 0 to shoot a 9-ball rack in play with two fouls in a row already.
std::unique_ptr<Match> twoFoulsDown(const protocol::MatchSettings& settings) {
  MatchOptions options = pacedOptions();
  options.settings = settings;
  auto m = seatedMatch(options);
  rules::GameState st = rules::newRack(1);
  st.phase = rules::Phase::Open;
  st.shooter = 0;
  st.ball_in_hand = rules::BallInHand::None;
  st.fouls_in_row = {2, 0};
  EXPECT_TRUE(m->setPosition(st, m->balls()));
  return m;
}

TEST(ShotClock, ExtensionThenAFoulThatEndsTheRackAndTheRaceGoesOn) {
  auto m = twoFoulsDown(nineBallRace(2, 5.0));
  EXPECT_FALSE(m->tickClock(100.0));  // starts the clock
  EXPECT_DOUBLE_EQ(*m->clockLeft(100.0), 5.0);
  EXPECT_FALSE(m->tickClock(104.9));
  EXPECT_EQ(m->extensionsLeft(0), 1);
  EXPECT_FALSE(m->tickClock(105.05));  // the extension: 5 s more
  EXPECT_EQ(m->extensionsLeft(0), 0);
  EXPECT_DOUBLE_EQ(m->clockTotal(), 10.0);
  EXPECT_FALSE(m->tickClock(109.9));
  const auto expired = m->tickClock(110.05);
  ASSERT_TRUE(expired);
  ASSERT_TRUE(expired->accepted());
  ASSERT_TRUE(expired->done);
  const rules::Verdict& v = expired->done->verdict;
  EXPECT_TRUE(v.hasFoul(rules::Foul::ShotClockExpired)) << rules::describe(v);
  EXPECT_EQ(v.end, rules::GameEnd::ThreeFouls);
  EXPECT_EQ(v.winner, 1);
  ASSERT_TRUE(expired->record);
  EXPECT_FALSE(expired->record->shoots);
  // A race to 2: the next rack is up at once, its winner breaking, the score 0-1.
  EXPECT_EQ(m->phase(), MatchPhase::Break);
  EXPECT_EQ(m->rack(), 2u);
  EXPECT_EQ(m->game().breaker, 1);
  EXPECT_EQ(m->seats()[1].racks_won, 1);
  EXPECT_EQ(m->extensionsLeft(0), 1);  // one extension per rack
}

TEST(ShotClock, AWonRaceEndsTheMatch) {
  auto m = twoFoulsDown(nineBallRace(1, 5.0));
  m->tickClock(0.0);
  m->tickClock(5.1);
  ASSERT_TRUE(m->tickClock(10.2));
  EXPECT_EQ(m->phase(), MatchPhase::Over);
  EXPECT_EQ(m->game().winner, 1);
  EXPECT_FALSE(m->tickClock(100.0));  // no clock once the match is over
}

TEST(ShotClock, TimeTheServerWasStoppedDoesNotCount) {
  auto m = twoFoulsDown(nineBallRace(3, 5.0));
  m->tickClock(0.0);
  m->tickClock(1.0);
  m->pause(100.0);  // stopped for 100 s
  EXPECT_NEAR(*m->clockLeft(101.0), 4.0, 1e-9);
  EXPECT_FALSE(m->tickClock(104.9));
  EXPECT_EQ(m->extensionsLeft(0), 1);
}

TEST(ShotClock, StartsOnceTheShootersViewHasShownTheShotToRest) {
  MatchOptions options = pacedOptions();
  options.settings.shot_clock = 5.0;
  options.unpaced = true;  // every frame due at once, as with --fast
  auto m = seatedMatch(options);
  m->tickClock(0.0);
  ASSERT_TRUE(m->clockLeft(0.0));
  ASSERT_TRUE(m->handleShot(breakShot(), 1.0).accepted());
  EXPECT_FALSE(m->clockLeft(1.0));  // no clock while the balls move
  const auto report = finishNow(*m, 1.0);
  ASSERT_TRUE(report);
  ASSERT_FALSE(report->events.empty());
  const double rest = report->events.back().t;
  ASSERT_GT(rest, 1.0);  // a break runs for seconds
  m->tickClock(1.0);
  // The frames went out at once, but the shooter sees the shot for its length: the clock waits.
  EXPECT_DOUBLE_EQ(*m->clockLeft(1.0 + rest), 5.0);
  EXPECT_NEAR(*m->clockLeft(1.0 + rest + kViewDelay + 2.0), 3.0, 1e-6);
}

TEST(ShotClock, AStoredExpiryIsReplayedWhereItHappened) {
  MatchOptions options = pacedOptions();
  options.settings = nineBallRace(3, 5.0);
  auto m = seatedMatch(options);
  m->tickClock(0.0);
  m->tickClock(5.1);  // the extension
  auto expired = m->tickClock(10.2);
  ASSERT_TRUE(expired && expired->record);
  // On the break a time-out hands the break over.
  EXPECT_EQ(m->game().breaker, 1);
  EXPECT_EQ(m->phase(), MatchPhase::Break);

  Match target("srv-2", "Replay", runner(), pacedOptions(), 42);
  MatchReplay replay(m->snapshot(), {*expired->record}, target, {kToken0, kToken1}, 0.0);
  EXPECT_EQ(target.settings().game, rules::Game::NineBall);
  EXPECT_FALSE(target.settings().clockOn());  // the replay's own clock does not run
  const auto again = replay.step(0.0);
  ASSERT_TRUE(again && again->accepted());
  EXPECT_TRUE(replay.differences().empty());
  EXPECT_EQ(replay.replayed(), 1u);
  EXPECT_EQ(target.game().breaker, 1);
  EXPECT_EQ(target.lastVerdict(), m->lastVerdict());
}

}  // namespace
}  // namespace pool::server::test
