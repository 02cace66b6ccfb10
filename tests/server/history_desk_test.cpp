// The server's answers to history requests: the stored stroke as stored, the bounds of a request,
// forged and unsigned requests refused, and each participant's and key's share.
#include <gtest/gtest.h>

#include "server/history_desk.h"
#include "store/store_fixture.h"
#include "store/stored_break.h"

namespace pool::server {
namespace {

class HistoryDeskTest : public ::testing::Test {
 protected:
  void SetUp() override {
    auto opened = store::MatchStore::open(scratch_.file("pool.db"));
    ASSERT_TRUE(opened) << opened.error();
    store_ = std::move(*opened);
    store_->setTable("wpa-9ft");
    store::test::storeBreak(*store_, broken_);
  }

  /// A request for `count` strokes of `match` from `first`, signed by `key`, from `sender`.
  net::IncomingHistory request(const std::string& match, std::uint32_t first, std::uint32_t count,
                               const protocol::KeyPair& key,
                               const std::string& sender = "participant a") {
    protocol::HistoryRequest r;
    r.client = "browser-gateway";
    r.request = ++number_;
    r.match = match;
    r.first_shot = first;
    r.count = count;
    protocol::signHistory(r, key);
    return {Result<protocol::HistoryRequest>::ok(std::move(r)), sender};
  }

  store::test::Scratch scratch_;
  std::unique_ptr<store::MatchStore> store_;
  store::test::BrokenMatch broken_;
  protocol::KeyPair key_ = protocol::generateKeyPair();
  std::uint32_t number_ = 0;
};

// The stroke comes back as the store has it: its layouts and event log, the cue, the verdict's
// line, the match's table, game and players, the request it answers.
TEST_F(HistoryDeskTest, AStoredStrokeComesBackAsStored) {
  HistoryDesk desk(*store_, "srv");
  const auto in = request("srv-1", 1, 4, key_);
  const auto shots = desk.answer(in, 0.0);
  ASSERT_EQ(shots.size(), 1u) << "one stroke is stored";
  const auto& s = shots[0];
  const auto& record = *broken_.answer.record;
  EXPECT_TRUE(s.found) << s.error;
  EXPECT_EQ(s.client, "browser-gateway");
  EXPECT_EQ(s.request, in.request->request);
  EXPECT_EQ(s.asker, key_.publicKey()) << "the answer names the key that asked";
  EXPECT_EQ(s.match, "srv-1");
  EXPECT_EQ(s.shot_number, 1u);
  EXPECT_EQ(s.shots, 1u);
  EXPECT_EQ(s.table, "wpa-9ft");
  EXPECT_EQ(s.game, rules::Game::EightBall);
  EXPECT_EQ(s.seat, record.command.seat);
  EXPECT_EQ(s.cue.speed, record.command.cue.speed);
  EXPECT_EQ(s.cue.yaw, record.command.cue.yaw);
  ASSERT_EQ(s.before.size(), record.before.size());
  for (std::size_t i = 0; i < s.before.size(); ++i) {
    EXPECT_EQ(s.before[i].pos, record.before[i].pos);
  }
  ASSERT_EQ(s.events.size(), record.events.size());
  for (std::size_t i = 0; i < s.events.size(); ++i) {
    EXPECT_EQ(s.events[i].t, record.events[i].t);
    EXPECT_EQ(s.events[i].pos, record.events[i].pos);
    EXPECT_EQ(s.events[i].type, record.events[i].type);
  }
  ASSERT_EQ(s.after.size(), record.after.size());
  for (std::size_t i = 0; i < s.after.size(); ++i) EXPECT_EQ(s.after[i].pos, record.after[i].pos);
  EXPECT_EQ(s.verdict_text, rules::describe(record.verdict));
  EXPECT_EQ(desk.counts().answered, 1u);
}

// What is not there is said in one line: a stroke past the match's last, another server's match,
// a match never stored. Nothing else is filled in.
TEST_F(HistoryDeskTest, WhatIsNotStoredIsSaidInOneLine) {
  HistoryDesk desk(*store_, "srv");
  for (const auto& [match, first, words] :
       std::vector<std::tuple<std::string, std::uint32_t, std::string>>{
           {"srv-1", 2, "match srv-1 has 1 shot: no shot 2"},
           {"other-1", 1, "not a match of server srv"},
           {"srv-9", 1, "no match srv-9 is stored"}}) {
    const auto shots = desk.answer(request(match, first, 1, key_), 0.0);
    ASSERT_EQ(shots.size(), 1u) << match;
    EXPECT_FALSE(shots[0].found) << match;
    EXPECT_EQ(shots[0].error, words);
    EXPECT_TRUE(shots[0].before.empty() && shots[0].events.empty()) << match;
  }
}

// A stroke still being played out (stored, its frames and result not all out) is not told: a
// replay must not give away the result before the table does.
TEST_F(HistoryDeskTest, AStrokeStillInMotionIsNotToldYet) {
  HistoryDesk desk(*store_, "srv");
  bool moving = true;
  desk.inMotion([&](const std::string& match, std::uint32_t shot) {
    return moving && match == "srv-1" && shot == 1;
  });
  auto shots = desk.answer(request("srv-1", 1, 1, key_), 0.0);
  ASSERT_EQ(shots.size(), 1u);
  EXPECT_FALSE(shots[0].found);
  EXPECT_EQ(shots[0].error, "shot 1 of srv-1 is still being played");
  EXPECT_TRUE(shots[0].events.empty());
  moving = false;
  shots = desk.answer(request("srv-1", 1, 1, key_), 1.0);
  ASSERT_EQ(shots.size(), 1u);
  EXPECT_TRUE(shots[0].found);
}

// A request someone else's key did not sign, or no key signed, or past its bounds, gets no answer
// at all (and reads nothing).
TEST_F(HistoryDeskTest, ForgedUnsignedAndUnboundedRequestsAreRefused) {
  HistoryDesk desk(*store_, "srv");
  auto forged = request("srv-1", 1, 1, key_);
  forged.request->first_shot = 2;  // the signature was made over shot 1
  std::string why;
  EXPECT_TRUE(desk.answer(forged, 0.0, &why).empty());
  EXPECT_EQ(why, "history request: not signed by the key it carries");
  auto stranger = request("srv-1", 1, 1, key_);
  stranger.request->public_key.assign(32, 7);  // another key put on a signed request
  EXPECT_TRUE(desk.answer(stranger, 0.0).empty());
  auto unsigned_request = request("srv-1", 1, 1, key_);
  unsigned_request.request->signature.clear();
  EXPECT_TRUE(desk.answer(unsigned_request, 0.0).empty());
  for (const std::uint32_t count : {0u, protocol::kMaxHistoryShots + 1}) {
    why.clear();
    EXPECT_TRUE(desk.answer(request("srv-1", 1, count, key_), 0.0, &why).empty()) << count;
    EXPECT_EQ(why, "count: 1 to 4 shots");
  }
  EXPECT_TRUE(desk.answer(request("srv-1", 0, 1, key_), 0.0).empty());
  const net::IncomingHistory unreadable{
      Result<protocol::HistoryRequest>::fail("history request: a text past its bound"), "p"};
  EXPECT_TRUE(desk.answer(unreadable, 0.0).empty());
  EXPECT_EQ(desk.counts().refused, 7u);
  EXPECT_EQ(desk.counts().answered, 0u);
}

// A participant's share and a key's share: kBurst at once, then kPerSecond a second. Many keys
// from one participant, or one key from many participants, are held to one share.
TEST_F(HistoryDeskTest, EachParticipantAndEachKeyHasAShare) {
  HistoryDesk desk(*store_, "srv");
  const int burst = static_cast<int>(HistoryDesk::kBurst);
  for (int i = 0; i < burst; ++i) {
    EXPECT_EQ(desk.answer(request("srv-1", 1, 1, key_, "participant a"), 0.0).size(), 1u) << i;
  }
  // The participant's share is spent, whichever key it signs with...
  EXPECT_TRUE(desk.answer(request("srv-1", 1, 1, protocol::generateKeyPair(), "participant a"), 0.0)
                  .empty());
  // ...and the key's, from whichever participant.
  EXPECT_TRUE(desk.answer(request("srv-1", 1, 1, key_, "participant b"), 0.0).empty());
  EXPECT_EQ(desk.counts().limited, 2u);
  // Someone else with a key of their own is answered.
  EXPECT_EQ(
      desk.answer(request("srv-1", 1, 1, protocol::generateKeyPair(), "participant c"), 0.0).size(),
      1u);
  // A second later the first participant has kPerSecond requests again.
  const int per_second = static_cast<int>(HistoryDesk::kPerSecond);
  for (int i = 0; i < per_second; ++i) {
    EXPECT_EQ(desk.answer(request("srv-1", 1, 1, key_, "participant a"), 1.0).size(), 1u) << i;
  }
  EXPECT_TRUE(desk.answer(request("srv-1", 1, 1, key_, "participant a"), 1.0).empty());
}

}  // namespace
}  // namespace pool::server
