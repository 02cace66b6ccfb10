// A player's record on the wire (PlayerStats): every field back as sent, sealed by the server so a
// changed or forged record no longer verifies, and unreadable keys, games and texts refused.
#include "net/player_stats_convert.h"

#include <gtest/gtest.h>

#include "net/server_seal.h"
#include "net/wire_fields.h"
#include "protocol/key_pair.h"

namespace pool::net {
namespace {

using namespace protocol;

PlayerStats record() {
  PlayerStats s;
  s.server = "srv";
  s.key = std::vector<std::uint8_t>(32, 0xA1);
  s.game = rules::Game::Snooker;
  s.name = "Ada";
  s.rating = 1562;
  s.rating_deviation = 80;
  s.matches = 3;
  s.matches_won = 2;
  s.racks = 7;
  s.racks_won = 5;
  s.strokes = 120;
  s.attempts = 90;
  s.pots = 45;
  s.breaks = 4;
  s.break_pots = 1;
  s.break_and_runs = 0;
  s.fouls = 6;
  s.safeties = 11;
  s.high_run = 54;
  return s;
}

TEST(PlayerStatsConvert, EveryFieldComesBackAndTheServersSealCoversThem) {
  auto wire = toWire(record());
  std::string hex;
  for (int i = 0; i < 32; ++i) hex += "a1";
  EXPECT_EQ(std::string(textOf(wire->player)), hex);  // the key in lower-case hex
  auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(*back, record());

  const KeyPair server = generateKeyPair();
  seal(*wire, server);
  const SealedSample sealed = sealedOf(*wire);
  EXPECT_EQ(sealed.kind, PublishedKind::PlayerStats);
  EXPECT_EQ(sealed.server, "srv");
  EXPECT_EQ(verifyPublished(sealed), SignatureCheck::Valid);
  wire->matches_won += 1;  // a record changed on the way (or forged) no longer verifies
  EXPECT_EQ(verifyPublished(sealedOf(*wire)), SignatureCheck::BadSignature);
}

TEST(PlayerStatsConvert, UnreadableRecordsAreRefused) {
  auto short_key = toWire(record());
  setText(short_key->player, "a1a1");
  EXPECT_FALSE(fromWire(*short_key));
  auto not_hex = toWire(record());
  setText(not_hex->player, std::string(64, 'z'));
  EXPECT_FALSE(fromWire(*not_hex));
  auto unknown_game = toWire(record());
  unknown_game->game = 7;
  EXPECT_FALSE(fromWire(*unknown_game));
}

}  // namespace
}  // namespace pool::net
