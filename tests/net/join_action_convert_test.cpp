// Join actions through the wire module: a concession crosses as JOIN_CONCEDE and keeps its
// signature valid; an action past the last one known is refused, in a request and in a reply.
#include <gtest/gtest.h>

#include "net/message_convert.h"
#include "net/messages.h"
#include "net/wire_fields.h"
#include "protocol/key_pair.h"
#include "protocol/seat_request.h"

namespace pool::net {
namespace {

TEST(JoinActionConvert, AConcessionCrossesSignedAndAnUnknownActionIsRefused) {
  const protocol::KeyPair key = protocol::generateKeyPair();
  protocol::SeatRequest r;
  r.client = "c0ffee";
  r.request = 4;
  r.match = "srv-1";
  r.action = protocol::JoinAction::Concede;
  r.seat = 1;
  r.token = 77;
  r.seq = 9;
  ASSERT_TRUE(protocol::changesSeat(r)) << "a concession must be signed";
  protocol::SeatRequest entry = r;
  entry.action = protocol::JoinAction::Enter;
  EXPECT_TRUE(protocol::changesSeat(entry)) << "an entry must be signed: the entrant is the key";
  protocol::signSeatRequest(r, key);
  auto wire = toWire(r);
  EXPECT_EQ(wire->action, pool_JOIN_CONCEDE);
  const auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(back->action, protocol::JoinAction::Concede);
  EXPECT_EQ(protocol::verifySeatRequest(*back, key.publicKey()), protocol::SignatureCheck::Valid);
  // Signed as a concession, it is no rematch.
  protocol::SeatRequest other = *back;
  other.action = protocol::JoinAction::Rematch;
  EXPECT_EQ(protocol::verifySeatRequest(other, key.publicKey()),
            protocol::SignatureCheck::BadSignature);

  // The last action known (a tournament entry, since version 10) crosses too; past it, none.
  setRawValue(wire->action, pool_JOIN_ENTER);
  ASSERT_TRUE(fromWire(*wire));
  EXPECT_EQ(fromWire(*wire)->action, protocol::JoinAction::Enter);
  setRawValue(wire->action, pool_JOIN_ENTER + 1);
  EXPECT_EQ(fromWire(*wire).error(), "action: not a known join action");

  pool_JoinReply reply{};
  reply.action = pool_JOIN_CONCEDE;
  reply.outcome = pool_JOIN_ACCEPTED;
  const auto answer = fromWire(reply);
  ASSERT_TRUE(answer) << answer.error();
  EXPECT_EQ(answer->action, protocol::JoinAction::Concede);
  setRawValue(reply.action, pool_JOIN_ENTER + 1);
  EXPECT_FALSE(fromWire(reply));
}

TEST(JoinActionConvert, ATournamentOpeningCrossesSignedAndAnUnknownFormatIsRefused) {
  const protocol::KeyPair key = protocol::generateKeyPair();
  protocol::SeatRequest r;
  r.client = "c0ffee";
  r.request = 5;
  r.match = protocol::kNewMatch;
  r.action = protocol::JoinAction::Enter;
  r.name = "Ann";
  r.seq = 3;
  protocol::MatchSettings settings;
  settings.game = rules::Game::TenBall;
  settings.race_to = 4;
  r.settings = settings;
  r.opening = protocol::TournamentOpening{protocol::TournamentFormat::DoubleElimination, 12, true};
  protocol::signSeatRequest(r, key);
  auto wire = toWire(r);
  EXPECT_EQ(wire->tournament_format, 1);
  EXPECT_EQ(wire->entrants, 12);
  EXPECT_TRUE(wire->handicap);
  const auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  ASSERT_TRUE(back->opening);
  EXPECT_EQ(*back->opening, *r.opening);
  EXPECT_EQ(back->settings->game, rules::Game::TenBall);
  EXPECT_EQ(back->settings->race_to, 4);
  EXPECT_EQ(protocol::verifySeatRequest(*back, key.publicKey()), protocol::SignatureCheck::Valid);
  // Each of the opening's fields is signed.
  for (int field = 0; field < 3; ++field) {
    protocol::SeatRequest changed = *back;
    if (field == 0) changed.opening->format = protocol::TournamentFormat::RoundRobin;
    if (field == 1) changed.opening->entrants = 13;
    if (field == 2) changed.opening->handicap = false;
    EXPECT_EQ(protocol::verifySeatRequest(changed, key.publicKey()),
              protocol::SignatureCheck::BadSignature)
        << field;
  }
  // An entry into an existing tournament carries no opening, whatever the fields say.
  setText(wire->match, "srv-t1");
  EXPECT_FALSE(fromWire(*wire)->opening);
  setText(wire->match, protocol::kNewMatch);
  wire->tournament_format = 3;
  EXPECT_EQ(fromWire(*wire).error(), "tournament_format: not a known format");
}

}  // namespace
}  // namespace pool::net
