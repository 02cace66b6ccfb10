// Replays on the wire: a history request comes back signed as sent (a changed field no longer
// verifies), a stored shot comes back with its layouts and events and the server's seal covers
// them; unreadable samples are refused.
#include "net/history_convert.h"

#include <gtest/gtest.h>

#include <cmath>

#include "net/server_seal.h"
#include "net/wire_fields.h"
#include "protocol/key_pair.h"

namespace pool::net {
namespace {

using namespace protocol;

HistoryRequest asked(const KeyPair& key) {
  HistoryRequest r;
  r.client = "web-1";
  r.request = 42;
  r.match = "srv-7";
  r.first_shot = 3;
  r.count = 2;
  signHistory(r, key);
  return r;
}

HistoryShot stored() {
  HistoryShot s;
  s.client = "web-1";
  s.request = 42;
  s.match = "srv-7";
  s.found = true;
  s.shot_number = 3;
  s.shots = 11;
  s.game = rules::Game::NineBall;
  s.table = "wpa-9ft";
  s.players = {"alice", "bob"};
  s.seat = 1;
  s.cue.yaw = 0.25;
  s.cue.tip_height = -0.3;
  s.cue.speed = 4.5;
  for (int id = 0; id < 3; ++id) {
    s.before.push_back(physics::restingBall(id, {0.1 * id, -0.2}, 0.028575));
  }
  s.after = s.before;
  s.after[1].state = physics::MotionState::Pocketed;
  s.after[1].pocket = "corner_foot_left";
  physics::Event strike;
  strike.type = physics::EventType::Strike;
  physics::Event hit;
  hit.t = 0.21;
  hit.type = physics::EventType::BallBall;
  hit.ball_a = 0;
  hit.ball_b = 1;
  hit.speed = 2.5;
  hit.pos = physics::Vec3(0.05, -0.2, 0.028575);
  s.events = {strike, hit};
  s.verdict_text = "seat 2 pots the 1";
  return s;
}

TEST(HistoryConvert, ARequestComesBackSignedAsSent) {
  const KeyPair key = generateKeyPair();
  auto wire = toWire(asked(key));
  auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->client, "web-1");
  EXPECT_EQ(back->request, 42u);
  EXPECT_EQ(back->match, "srv-7");
  EXPECT_EQ(back->first_shot, 3u);
  EXPECT_EQ(back->count, 2u);
  EXPECT_EQ(verifyHistory(*back), SignatureCheck::Valid);
  EXPECT_TRUE(checkHistoryRequest(*back));
  // Every signed field counts: a request changed on the way no longer verifies.
  for (auto change : std::vector<void (*)(HistoryRequest&)>{
           [](HistoryRequest& r) { r.client = "web-2"; }, [](HistoryRequest& r) { ++r.request; },
           [](HistoryRequest& r) { r.match = "srv-8"; }, [](HistoryRequest& r) { ++r.first_shot; },
           [](HistoryRequest& r) { ++r.count; }}) {
    HistoryRequest changed = *back;
    change(changed);
    EXPECT_EQ(verifyHistory(changed), SignatureCheck::BadSignature);
  }
}

TEST(HistoryConvert, UnreadableRequestsAreRefused) {
  const KeyPair key = generateKeyPair();
  auto short_key = toWire(asked(key));
  setBytes(short_key->public_key, std::vector<std::uint8_t>(16, 1), 32);
  EXPECT_FALSE(fromWire(*short_key));
  auto bad = asked(key);
  bad.count = kMaxHistoryShots + 1;
  EXPECT_FALSE(checkHistoryRequest(bad));
  bad.count = 1;
  bad.first_shot = 0;
  EXPECT_FALSE(checkHistoryRequest(bad));
  bad.first_shot = 1;
  bad.match = std::string(41, 'x');
  EXPECT_FALSE(checkHistoryRequest(bad));
}

TEST(HistoryConvert, AStoredShotComesBackAndTheServersSealCoversIt) {
  auto wire = toWire(stored());
  auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  const HistoryShot want = stored();
  EXPECT_EQ(back->shot_number, want.shot_number);
  EXPECT_EQ(back->shots, want.shots);
  EXPECT_EQ(back->game, want.game);
  EXPECT_EQ(back->table, want.table);
  EXPECT_EQ(back->players, want.players);
  EXPECT_EQ(back->seat, want.seat);
  EXPECT_EQ(back->cue.yaw, want.cue.yaw);
  EXPECT_EQ(back->cue.tip_height, want.cue.tip_height);
  EXPECT_EQ(back->cue.speed, want.cue.speed);
  ASSERT_EQ(back->before.size(), 3u);
  EXPECT_EQ(back->before[2].pos, want.before[2].pos);
  ASSERT_EQ(back->after.size(), 3u);
  EXPECT_EQ(back->after[1].state, physics::MotionState::Pocketed);
  EXPECT_EQ(back->after[1].pocket, "corner_foot_left");
  ASSERT_EQ(back->events.size(), 2u);
  EXPECT_EQ(back->events[1].type, physics::EventType::BallBall);
  EXPECT_EQ(back->events[1].ball_b, 1);
  EXPECT_EQ(back->events[1].pos, want.events[1].pos);
  EXPECT_EQ(back->verdict_text, want.verdict_text);

  const KeyPair server = generateKeyPair();
  seal(*wire, server);
  const SealedSample sealed = sealedOf(*wire);
  EXPECT_EQ(sealed.kind, PublishedKind::HistoryShot);
  EXPECT_EQ(sealed.server, "srv");
  EXPECT_EQ(verifyPublished(sealed), SignatureCheck::Valid);
  wire->events._buffer[1].pos.x += 0.01;  // a shot replayed other than stored
  EXPECT_EQ(verifyPublished(sealedOf(*wire)), SignatureCheck::BadSignature);
}

TEST(HistoryConvert, UnreadableShotsAreRefused) {
  auto unknown_game = toWire(stored());
  unknown_game->game = 7;
  EXPECT_FALSE(fromWire(*unknown_game));
  // An event past any shot's time (a replay would be hours of frames), or no time at all.
  for (const double t : {-0.5, 120.5, 3e4, std::nan("")}) {
    auto late = stored();
    late.events[1].t = t;
    const auto read = fromWire(*toWire(late));
    ASSERT_FALSE(read) << t;
    EXPECT_EQ(read.error(), "history shot: events[1]: event time out of range (0 to 120 s)");
  }
  HistoryShot none;
  none.client = "web-1";
  none.match = "srv-7";
  none.error = "no match srv-7 is stored";
  auto back = fromWire(*toWire(none));
  ASSERT_TRUE(back) << back.error();
  EXPECT_FALSE(back->found);
  EXPECT_EQ(back->error, none.error);
}

}  // namespace
}  // namespace pool::net
