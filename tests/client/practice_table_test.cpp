// A practice table driven by a headless client against a real pool-server over loopback DDS:
// lay out, shoot, undo (bit-identical), shoot again, save as a pool-sim scenario that gives the
// same events, load it back; the commands of strangers, replays and bad coefficients refused; and
// a snooker practice table's 22 balls laid out over the wire.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "client/net/game_client.h"
#include "net/client_transport.h"
#include "physics/events.h"
#include "protocol/practice_request.h"
#include "scenario/scenario.h"
#include "scenario/scenario_write.h"
#include "support/client_fixture.h"
#include "table/rack.h"

namespace pool::client::test {
namespace {

using namespace std::chrono_literals;
using protocol::PracticeAction;
using protocol::PracticeRequest;

/// A headless practice player: a GameClient and every shot result it was handed.
struct Player {
  Player(std::uint32_t domain, const std::string& name) : client({domain, "", name, {}, {}}) {}

  bool pumpUntil(const std::function<bool()>& done, std::chrono::milliseconds timeout = 30s) {
    const auto deadline = std::chrono::steady_clock::now() + timeout;
    for (;;) {
      for (auto& e : client.poll()) {
        if (auto* r = std::get_if<ShotReport>(&e)) reports.push_back(*r);
        if (auto* a = std::get_if<JoinAnswer>(&e)) answers.push_back(*a);
      }
      if (done()) return true;
      if (std::chrono::steady_clock::now() >= deadline) return false;
      client.wait(20ms);
    }
  }

  /// The first answer to `seq` that satisfies `ok` (final: with its verdict), waiting for it.
  std::optional<ShotReport> answer(std::uint32_t seq, bool final = true) {
    std::optional<ShotReport> found;
    pumpUntil([&] {
      for (const auto& r : reports) {
        if (r.seq == seq && (!final || !r.accepted || r.final())) found = r;
      }
      return found.has_value();
    });
    return found;
  }

  const MatchView* state() const { return client.state(client.seat()->match); }

  /// Sends `request` and waits for its final answer.
  std::optional<ShotReport> practice(PracticeRequest request) {
    auto seq = client.practice(std::move(request));
    EXPECT_TRUE(seq) << (seq ? "" : seq.error());
    return seq ? answer(*seq) : std::nullopt;
  }

  GameClient client;
  std::vector<ShotReport> reports;
  std::vector<JoinAnswer> answers;
};

PracticeRequest action(PracticeAction what) {
  PracticeRequest r;
  r.action = what;
  return r;
}

bool sameBits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// Every field of every ball equal bit for bit.
::testing::AssertionResult bitIdentical(const std::vector<physics::Ball>& a,
                                        const std::vector<physics::Ball>& b) {
  if (a.size() != b.size()) return ::testing::AssertionFailure() << "ball counts differ";
  for (std::size_t i = 0; i < a.size(); ++i) {
    const auto& x = a[i];
    const auto& y = b[i];
    const double xs[] = {x.pos.x(),     x.pos.y(),     x.pos.z(),    x.orient.w(), x.orient.x(),
                         x.orient.y(),  x.orient.z(),  x.vel.x(),    x.vel.y(),    x.vel.z(),
                         x.ang_vel.x(), x.ang_vel.y(), x.ang_vel.z()};
    const double ys[] = {y.pos.x(),     y.pos.y(),     y.pos.z(),    y.orient.w(), y.orient.x(),
                         y.orient.y(),  y.orient.z(),  y.vel.x(),    y.vel.y(),    y.vel.z(),
                         y.ang_vel.x(), y.ang_vel.y(), y.ang_vel.z()};
    for (std::size_t k = 0; k < std::size(xs); ++k) {
      if (!sameBits(xs[k], ys[k])) {
        return ::testing::AssertionFailure() << "ball " << x.id << " differs in value " << k;
      }
    }
    if (x.id != y.id || x.state != y.state || x.pocket != y.pocket) {
      return ::testing::AssertionFailure() << "ball " << x.id << " differs in id or state";
    }
  }
  return ::testing::AssertionSuccess();
}

class PracticeTableTest : public ClientIntegrationTest {
 protected:
  /// Opens a practice table of `game` at the server's free one with `player`; returns its match
  /// id.
  std::string openPractice(Player& player, rules::Game game = rules::Game::EightBall) {
    EXPECT_TRUE(player.pumpUntil([&] { return !player.client.lobby().empty(); })) << logs();
    protocol::MatchSettings practice;
    practice.practice = true;
    practice.game = game;
    player.client.setTableSettings(practice);
    player.client.requestSeat("new");
    EXPECT_TRUE(player.pumpUntil([&] {
      return player.client.seat() && player.state() && player.state()->settings.practice &&
             protocol::inPlay(player.state()->phase);
    })) << logs();
    return player.client.seat() ? player.client.seat()->match : "";
  }

  /// The three-ball layout of these tests: the cue ball, the 1 and the 2.
  static PracticeRequest layout() {
    PracticeRequest r = action(PracticeAction::Layout);
    r.balls = {{0, -0.6, 0.1}, {1, 0.3, 0.05}, {2, 0.7, -0.25}};
    return r;
  }

  /// A firm shot at the 1 from the layout's cue ball, with a little side and draw.
  static protocol::ShotRequest shot() {
    protocol::ShotRequest r;
    r.cue.yaw = std::atan2(0.05 - 0.1, 0.3 + 0.6) + 0.01;
    r.cue.tip_side = 0.1;
    r.cue.tip_height = -0.2;
    r.cue.elevation = 0.05;
    r.cue.speed = 3.0;
    return r;
  }
};

TEST_F(PracticeTableTest, LayOutShootUndoAgainSaveAndLoad) {
  open(kPractice, "practice");
  startServer({"--fast"});
  Player ada(kPractice, "Ada");
  const std::string match = openPractice(ada);
  ASSERT_FALSE(match.empty());
  EXPECT_TRUE(ada.state()->standard_physics);
  EXPECT_EQ(ada.state()->ball_in_hand, rules::BallInHand::Anywhere);

  // Lay out three balls.
  auto laid = ada.practice(layout());
  ASSERT_TRUE(laid && laid->accepted) << (laid ? laid->reject_text : "no answer") << logs();
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->balls.size() == 3; })) << logs();
  const std::vector<physics::Ball> placed = ada.state()->balls;
  const std::uint32_t placed_revision = ada.state()->revision;
  EXPECT_EQ(placed[1].pos.x(), 0.3);

  // Shoot: the table changes; the shot's events come with its final result.
  auto seq = ada.client.shoot(shot());
  ASSERT_TRUE(seq);
  auto first = ada.answer(*seq);
  ASSERT_TRUE(first && first->accepted) << (first ? first->reject_text : "no answer") << logs();
  ASSERT_GT(first->events.size(), 3u);
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->shot_number == 1; })) << logs();
  const std::vector<physics::Ball> after_shot = ada.state()->balls;
  EXPECT_FALSE(bitIdentical(after_shot, placed));
  EXPECT_EQ(ada.state()->undo_depth, 2);  // the layout and the shot

  // Undo: the table is bit for bit as it was before the shot.
  auto undone = ada.practice(action(PracticeAction::Undo));
  ASSERT_TRUE(undone && undone->accepted) << (undone ? undone->reject_text : "") << logs();
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->undo_depth == 1; })) << logs();
  EXPECT_TRUE(bitIdentical(ada.state()->balls, placed));
  EXPECT_GT(ada.state()->revision, placed_revision);

  // Again: undo is refused (the last change was undone, not a shot); the shot itself once more.
  auto again_refused = ada.practice(action(PracticeAction::Again));
  ASSERT_TRUE(again_refused);
  EXPECT_FALSE(again_refused->accepted);
  EXPECT_EQ(again_refused->reject_reason, protocol::RejectReason::BadPractice);
  seq = ada.client.shoot(shot());
  ASSERT_TRUE(seq);
  auto second = ada.answer(*seq);
  ASSERT_TRUE(second && second->accepted);
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->undo_depth == 2; })) << logs();
  auto third = ada.practice(action(PracticeAction::Again));  // the table before it, the same shot
  ASSERT_TRUE(third && third->accepted) << (third ? third->reject_text : "") << logs();
  ASSERT_EQ(third->events.size(), first->events.size());
  for (std::size_t i = 0; i < first->events.size(); ++i) {
    EXPECT_TRUE(sameBits(third->events[i].t, first->events[i].t)) << "event " << i;
    EXPECT_EQ(third->events[i].type, first->events[i].type) << "event " << i;
  }
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->shot_number == 3; })) << logs();
  EXPECT_TRUE(bitIdentical(ada.state()->balls, after_shot));

  // Save the table before the shot and the shot as a scenario: pool-sim gives the same events.
  scenario::ScenarioSource source;
  source.table = "wpa-9ft";
  for (std::size_t i = 0; i < protocol::kPracticeCoefficients.size(); ++i) {
    source.params.emplace_back(protocol::kPracticeCoefficients[i], ada.state()->coefficients[i]);
  }
  source.balls = placed;
  source.shot = shot().cue;
  const std::string path = file("practice.json");
  std::ofstream(path) << scenario::scenarioJson(source);
  ChildProcess& sim = start("pool-sim", {path}, "pool-sim");
  ASSERT_EQ(sim.waitExit(60s), 0) << sim.err();
  const auto result = nlohmann::json::parse(sim.out());
  const auto& events = result.at("events");
  ASSERT_EQ(events.size(), first->events.size());
  for (std::size_t i = 0; i < events.size(); ++i) {
    EXPECT_EQ(events[i].at("type").get<std::string>(), physics::toString(first->events[i].type))
        << "event " << i;
    EXPECT_NEAR(events[i].at("t").get<double>(), first->events[i].t, 1e-9) << "event " << i;
  }

  // Load it back: the scenario's balls laid out on the table, exactly where the file puts them.
  auto loaded = scenario::loadScenario(path);
  ASSERT_TRUE(loaded) << loaded.error();
  PracticeRequest load = action(PracticeAction::Layout);
  for (const auto& b : loaded->balls) load.balls.push_back({b.id, b.pos.x(), b.pos.y()});
  auto back = ada.practice(load);
  ASSERT_TRUE(back && back->accepted) << (back ? back->reject_text : "") << logs();
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->undo_depth == 3; })) << logs();
  EXPECT_TRUE(bitIdentical(ada.state()->balls, placed));

  // Re-rack 9-ball, then clear the table: the cue ball alone.
  PracticeRequest rack = action(PracticeAction::Rack);
  rack.rack = 9;
  auto racked = ada.practice(rack);
  ASSERT_TRUE(racked && racked->accepted);
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->balls.size() == 10; })) << logs();
  EXPECT_EQ(ada.state()->settings.game, rules::Game::NineBall);
  rack.rack = 0;
  auto cleared = ada.practice(rack);
  ASSERT_TRUE(cleared && cleared->accepted);
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->balls.size() == 1; })) << logs();
  EXPECT_EQ(ada.state()->balls[0].id, physics::kCueBall);
}

TEST_F(PracticeTableTest, StrangersReplaysAndBadValuesAreRefusedAndChangeNothing) {
  open(kPracticeAttacks, "practice-attacks");
  startServer({"--fast"});
  Player ada(kPracticeAttacks, "Ada");
  const std::string match = openPractice(ada);
  ASSERT_FALSE(match.empty());
  auto laid = ada.practice(layout());
  ASSERT_TRUE(laid && laid->accepted) << logs();
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->balls.size() == 3; })) << logs();
  const std::vector<physics::Ball> before = ada.state()->balls;
  const std::uint64_t token = ada.client.seat()->token;

  // A stranger on the domain, with its own key, writing practice commands for Ada's seat.
  net::ClientTransport stranger(kPracticeAttacks, {});
  // It reads the match's partition, as anyone on the domain may, to see the answers.
  ASSERT_TRUE(stranger.follow({match}).empty());
  const auto stranger_key = protocol::generateKeyPair();
  std::vector<ShotReport> seen;
  const auto answerTo = [&](std::uint32_t seq) -> std::optional<ShotReport> {
    std::optional<ShotReport> found;
    ada.pumpUntil([&] {
      for (auto& r : stranger.takeResults()) {
        if (r) seen.push_back(*r);
      }
      for (const auto& r : seen) {
        if (r.match == match && r.seat == 0 && r.seq == seq) found = r;
      }
      return found.has_value();
    });
    return found;
  };
  const auto forged = [&](std::uint32_t seq, std::uint64_t with_token) {
    PracticeRequest r = action(PracticeAction::Rack);
    r.rack = 8;
    r.match = match;
    r.seat = 0;
    r.seat_token = with_token;
    r.seq = seq;
    protocol::signPractice(r, stranger_key);
    return r;
  };
  // Wait until the stranger's practice writer is matched by the server's reader.
  ASSERT_TRUE(ada.pumpUntil([&] { return !stranger.takeLobby().empty(); })) << logs();

  ASSERT_TRUE(stranger.send(forged(1000, token + 1)).empty());
  auto bad_token = answerTo(1000);
  ASSERT_TRUE(bad_token) << logs();
  EXPECT_EQ(bad_token->reject_reason, protocol::RejectReason::BadToken);

  ASSERT_TRUE(stranger.send(forged(1001, token)).empty());
  auto bad_signature = answerTo(1001);
  ASSERT_TRUE(bad_signature) << logs();
  EXPECT_EQ(bad_signature->reject_reason, protocol::RejectReason::BadSignature);

  // Ada's own layout command replayed byte for byte: its number is used up.
  PracticeRequest replay = layout();
  replay.match = match;
  replay.seat = 0;
  replay.seat_token = token;
  replay.seq = laid->seq;
  protocol::signPractice(replay, ada.client.key());
  ASSERT_TRUE(stranger.send(replay).empty());
  bool refused_stale = false;
  ada.pumpUntil([&] {
    for (auto& r : stranger.takeResults()) {
      if (r) seen.push_back(*r);
    }
    for (const auto& r : seen) {
      refused_stale |=
          r.seq == replay.seq && r.reject_reason == protocol::RejectReason::StaleSequence;
    }
    return refused_stale;
  });
  EXPECT_TRUE(refused_stale);

  // Ada's own commands with bad values: coefficients out of range, an overlapping layout, a
  // layout without the cue ball, nothing to undo after a fresh table... each refused.
  PracticeRequest physics = action(PracticeAction::Physics);
  physics.coefficients = ada.state()->coefficients;
  physics.coefficients[0] = 5.0;  // u_s
  auto bad_physics = ada.practice(physics);
  ASSERT_TRUE(bad_physics);
  EXPECT_FALSE(bad_physics->accepted);
  EXPECT_EQ(bad_physics->reject_reason, protocol::RejectReason::BadPractice);
  EXPECT_NE(bad_physics->reject_text.find("u_s"), std::string::npos) << bad_physics->reject_text;
  PracticeRequest overlap = action(PracticeAction::Layout);
  overlap.balls = {{0, 0.0, 0.0}, {1, 0.01, 0.0}};
  auto bad_layout = ada.practice(overlap);
  ASSERT_TRUE(bad_layout);
  EXPECT_EQ(bad_layout->reject_reason, protocol::RejectReason::BadPractice);
  PracticeRequest no_cue = action(PracticeAction::Layout);
  no_cue.balls = {{1, 0.0, 0.0}};
  auto bad_no_cue = ada.practice(no_cue);
  ASSERT_TRUE(bad_no_cue);
  EXPECT_EQ(bad_no_cue->reject_reason, protocol::RejectReason::BadPractice);
  PracticeRequest off = action(PracticeAction::Layout);
  off.balls = {{0, 5.0, 0.0}};
  auto bad_off = ada.practice(off);
  ASSERT_TRUE(bad_off);
  EXPECT_EQ(bad_off->reject_reason, protocol::RejectReason::Malformed);

  // Nothing changed: the same balls, standard physics; then a valid change goes through.
  const std::uint32_t revision = ada.state()->revision;
  EXPECT_TRUE(bitIdentical(ada.state()->balls, before));
  EXPECT_TRUE(ada.state()->standard_physics);
  physics.coefficients = ada.state()->coefficients;
  physics.coefficients[0] = 0.25;
  auto good_physics = ada.practice(physics);
  ASSERT_TRUE(good_physics && good_physics->accepted) << logs();
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->revision > revision; })) << logs();
  EXPECT_FALSE(ada.state()->standard_physics);
  EXPECT_EQ(ada.state()->coefficients[0], 0.25);
  const LobbyEntry* entry = nullptr;
  ASSERT_TRUE(ada.pumpUntil([&] {
    entry = ada.client.lobby().find(match);
    return entry && !entry->standard_physics;
  }));
  EXPECT_TRUE(bitIdentical(ada.state()->balls, before));
}

TEST_F(PracticeTableTest, AFriendShootsTooAndASpectatorWatches) {
  open(kPracticeFriend, "practice-friend");
  startServer({"--fast"});
  Player ada(kPracticeFriend, "Ada");
  const std::string match = openPractice(ada);
  ASSERT_FALSE(match.empty());
  Player bob(kPracticeFriend, "Bob");
  Player eve(kPracticeFriend, "Eve");
  bob.client.requestSeat(match);
  eve.client.requestSpectate(match);
  ASSERT_TRUE(bob.pumpUntil([&] { return bob.client.seat() && bob.state(); })) << logs();
  EXPECT_EQ(bob.client.seat()->seat, 1);
  // Bob lays out and shoots though Ada shot nothing; Ada's undo takes his shot back; Eve sees it.
  auto laid = bob.practice(layout());
  ASSERT_TRUE(laid && laid->accepted) << (laid ? laid->reject_text : "") << logs();
  auto seq = bob.client.shoot(shot());
  ASSERT_TRUE(seq);
  auto bobs = bob.answer(*seq);
  ASSERT_TRUE(bobs && bobs->accepted) << (bobs ? bobs->reject_text : "") << logs();
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->shot_number == 1; })) << logs();
  auto undone = ada.practice(action(PracticeAction::Undo));
  ASSERT_TRUE(undone && undone->accepted) << logs();
  ASSERT_TRUE(eve.pumpUntil([&] {
    const MatchView* v = eve.client.state(match);
    return v && v->shot_number == 1 && v->undo_depth == 1;
  })) << logs();
  EXPECT_EQ(eve.client.state(match)->balls.size(), 3u);
  EXPECT_EQ(eve.client.state(match)->seats[1].name, "Bob");
}

TEST_F(PracticeTableTest, ARestartEndsPracticeTablesAndTheServerGoesOn) {
  open(kPracticeRestart, "practice-restart");
  const std::string db = file("pool.db");
  const auto serverRun = [&](int run) -> ChildProcess& {
    return start("pool-server",
                 {"--domain", std::to_string(domain_), "--tables", "1", "--server-id", "srv",
                  "--fast", "--db", db},
                 "server" + std::to_string(run));
  };
  ChildProcess* server = &serverRun(1);
  Player ada(kPracticeRestart, "Ada");
  const std::string match = openPractice(ada);
  ASSERT_FALSE(match.empty());
  auto laid = ada.practice(layout());
  ASSERT_TRUE(laid && laid->accepted) << logs();
  auto seq = ada.client.shoot(shot());
  ASSERT_TRUE(seq && ada.answer(*seq)) << logs();
  const std::uint64_t token = ada.client.seat()->token;

  server->kill(SIGKILL);
  server = &serverRun(2);
  // The restarted server opens its free table under the next id (srv-1 was its free table, srv-2
  // the practice table: their numbers are not given again).
  Player again(kPracticeRestart, "Ada");
  ASSERT_TRUE(again.pumpUntil([&] { return again.client.lobby().find("srv-3") != nullptr; }))
      << server->out() << server->err();
  // The practice table is gone: taking it back is refused.
  std::optional<JoinAnswer> answer;
  const std::uint32_t asked = again.client.requestRejoin(match, token, 0);
  ASSERT_TRUE(again.pumpUntil([&] {
    for (const auto& a : again.answers) {
      if (a.request == asked) answer = a;
    }
    return answer.has_value();
  })) << logs();
  EXPECT_EQ(answer->outcome, JoinOutcome::NoSuchMatch) << answer->reason;
  // A new practice table opens and works after the restart.
  const std::string fresh = openPractice(again);
  ASSERT_FALSE(fresh.empty());
  EXPECT_NE(fresh, match);  // ids are not reused
  auto relaid = again.practice(layout());
  ASSERT_TRUE(relaid && relaid->accepted) << logs();
  EXPECT_TRUE(server->running());
}

TEST_F(PracticeTableTest, ASnookerPracticeTableTakesItsTwentyTwoBallsOverTheWire) {
  open(kPracticeSnooker, "practice-snooker");
  startServer({"--fast"});
  Player ada(kPracticeSnooker, "Ada");
  const std::string match = openPractice(ada, rules::Game::Snooker);
  ASSERT_FALSE(match.empty());
  // The lobby and the table's state may come in either order: both are waited for.
  ASSERT_TRUE(ada.pumpUntil([&] {
    const LobbyEntry* entry = ada.client.lobby().find(match);
    const MatchView* state = ada.state();
    return entry && entry->table == "snooker-12ft" && state &&
           state->settings.game == rules::Game::Snooker && state->balls.size() == 22u;
  })) << "no snooker practice table of 22 balls\n"
      << logs();

  // Every ball where it lies and the blue dragged to the top cushion's end of the table, 1.6 m
  // up it (beyond a pool table's end): 22 balls, signed past the 16 fixed slots.
  PracticeRequest drag = action(PracticeAction::Layout);
  for (const auto& b : ada.state()->balls) {
    drag.balls.push_back({b.id, b.pos.x(), b.pos.y()});
    if (b.id == table::kSnookerBlue) drag.balls.back() = {b.id, 1.6, -0.7};
  }
  auto laid = ada.practice(drag);
  ASSERT_TRUE(laid && laid->accepted) << (laid ? laid->reject_text : "no answer") << logs();
  ASSERT_TRUE(ada.pumpUntil([&] { return ada.state()->undo_depth == 1; })) << logs();
  ASSERT_EQ(ada.state()->balls.size(), 22u);
  EXPECT_EQ(ada.state()->balls[table::kSnookerBlue].pos.x(), 1.6);

  // An 8-ball rack is another table's: refused in one line, nothing changed.
  PracticeRequest rack = action(PracticeAction::Rack);
  rack.rack = 8;
  auto refused = ada.practice(rack);
  ASSERT_TRUE(refused);
  EXPECT_FALSE(refused->accepted);
  EXPECT_EQ(refused->reject_reason, protocol::RejectReason::BadPractice);
  EXPECT_EQ(refused->reject_text,
            "rack: this is a snooker table; it racks 22 (snooker) or 0 (clear)");
  EXPECT_EQ(ada.state()->undo_depth, 1);
  EXPECT_EQ(ada.state()->settings.game, rules::Game::Snooker);
}

}  // namespace
}  // namespace pool::client::test
