// A tournament on the wire (TournamentInfo): every field back as sent, the server's seal covering
// the bracket (a forged or changed bracket no longer verifies), unreadable samples refused.
#include "net/tournament_convert.h"

#include <gtest/gtest.h>

#include "net/server_seal.h"
#include "net/wire_fields.h"
#include "protocol/key_pair.h"

namespace pool::net {
namespace {

using namespace protocol;

TournamentView cup() {
  TournamentView v;
  v.tournament = "srv-t3";
  v.server = "srv";
  v.name = "Club night";
  v.format = TournamentFormat::DoubleElimination;
  v.game = rules::Game::NineBall;
  v.race_to = 3;
  v.phase = TournamentPhase::Running;
  v.capacity = 4;
  for (int i = 0; i < 4; ++i) {
    v.entrants.push_back({"p" + std::to_string(i), std::string(64, 'a' + static_cast<char>(i)),
                          1500 + i, i + 1, 0, i == 3});
  }
  v.matches.push_back({"WB R1", 0, 3, 3, 0, 3, 1, false, "srv-4"});
  v.matches.push_back({"WB R1", 1, 2, 2, -1, 0, 0, false, "srv-5", 0, 2});
  v.matches.push_back({"LB R1", 3, -1, 0, -1, 0, 0, false, ""});
  v.handicap = true;
  v.opened_by = "Zoë";
  return v;
}

TEST(TournamentConvert, EveryFieldComesBackAndTheServersSealCoversTheBracket) {
  auto wire = toWire(cup());
  auto back = fromWire(*wire);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(*back, cup());
  const KeyPair server = generateKeyPair();
  seal(*wire, server);
  const SealedSample sealed = sealedOf(*wire);
  EXPECT_EQ(sealed.kind, PublishedKind::TournamentInfo);
  EXPECT_EQ(sealed.server, "srv");
  EXPECT_EQ(verifyPublished(sealed), SignatureCheck::Valid);
  wire->matches._buffer[0].winner = 3;  // a result changed on the way (or forged)
  EXPECT_EQ(verifyPublished(sealedOf(*wire)), SignatureCheck::BadSignature);
  const KeyPair forger = generateKeyPair();
  seal(*wire, forger);  // signed by someone else's key: valid, but not the pinned server's
  EXPECT_NE(sealedOf(*wire).server_key,
            std::vector<std::uint8_t>(server.public_key.begin(), server.public_key.end()));
}

TEST(TournamentConvert, UnreadableTournamentsAreRefused) {
  auto bad_entrant = toWire(cup());
  bad_entrant->matches._buffer[1].b = 4;  // no entrant 4 in a field of four
  EXPECT_FALSE(fromWire(*bad_entrant));
  auto bad_game = toWire(cup());
  bad_game->game = 7;
  EXPECT_FALSE(fromWire(*bad_game));
  auto bad_champion = toWire(cup());
  bad_champion->champion = 9;
  EXPECT_FALSE(fromWire(*bad_champion));
  auto bad_state = toWire(cup());
  bad_state->matches._buffer[0].state = 4;
  EXPECT_FALSE(fromWire(*bad_state));
}

}  // namespace
}  // namespace pool::net
