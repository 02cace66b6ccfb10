// Test helpers for matches without DDS: the real 9-ft table loaded once, seated matches, commands.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <memory>
#include <numbers>
#include <string>

#include "game/loaded_table.h"
#include "protocol/command_signature.h"
#include "protocol/key_pair.h"
#include "protocol/protocol_version.h"
#include "protocol/seat_request.h"
#include "protocol/shot_request.h"
#include "server/match/match.h"
#include "server/match/match_registry.h"

namespace pool::server::test {

/// The 9-ft table, loaded once for the whole test program.
inline std::shared_ptr<const game::LoadedTable> nineFoot() {
  static const auto kit = [] {
    auto loaded = game::loadSharedTable("wpa-9ft");
    EXPECT_TRUE(loaded) << loaded.error();
    return loaded ? *loaded : nullptr;
  }();
  return kit;
}

/// One runner on the 9-ft table, shared like a server shares it.
inline std::shared_ptr<ShotRunner> runner() {
  static const auto shared = std::make_shared<ShotRunner>(nineFoot());
  return shared;
}

/// Options: 60 Hz frames, paced, standard calls.
inline MatchOptions pacedOptions() {
  return MatchOptions{};
}

constexpr std::uint64_t kToken0 = 0x1111;
constexpr std::uint64_t kToken1 = 0x2222;

/// The key pair of the test client `client` (made once per test program).
inline const protocol::KeyPair& keyOf(const std::string& client) {
  static std::map<std::string, protocol::KeyPair> keys;
  auto it = keys.find(client);
  if (it == keys.end()) it = keys.emplace(client, protocol::generateKeyPair()).first;
  return it->second;
}
inline std::vector<std::uint8_t> publicKeyOf(const std::string& client) {
  return keyOf(client).publicKey();
}

/// The client that seatedMatch seats in `seat`: "a" in 0, "b" in 1.
inline std::string clientOf(int seat) {
  return seat == 1 ? "b" : "a";
}

/// `r` signed by the player seatedMatch put in its seat (a command for another seat number is
/// signed by seat 0's player).
inline protocol::ShotRequest sealed(protocol::ShotRequest r) {
  protocol::signCommand(r, keyOf(clientOf(r.seat)));
  return r;
}

/// A seat request (Rejoin, Leave, Rematch) for `seat` of "srv-1" held with `token`, from
/// `client`, carrying `client`'s public key and number `seq`, signed by `signer`'s key (default:
/// the client's own; another signer's signature cannot verify, as a forger's).
inline protocol::SeatRequest seatRequest(protocol::JoinAction action, const std::string& client,
                                         int seat, std::uint64_t token, std::uint32_t seq,
                                         const std::string& signer = {}) {
  protocol::SeatRequest r;
  r.client = client;
  r.protocol_version = protocol::kProtocolVersion;
  r.match = "srv-1";
  r.action = action;
  r.seat = seat;
  r.token = token;
  r.seq = seq;
  protocol::signSeatRequest(r, keyOf(signer.empty() ? client : signer));
  r.public_key = publicKeyOf(client);
  return r;
}

/// `r` without its signature.
inline protocol::SeatRequest unsignedCopy(protocol::SeatRequest r) {
  r.signature.clear();
  return r;
}

/// A match with "Ada" (client a, seat 0) and "Bob" (client b, seat 1) seated: the rack is up.
inline std::unique_ptr<Match> seatedMatch(MatchOptions options = pacedOptions()) {
  auto m = std::make_unique<Match>("srv-1", "Table 1", runner(), options, 42);
  EXPECT_TRUE(m->takeSeat(0, "Ada", "a", kToken0, publicKeyOf("a")).accepted());
  EXPECT_TRUE(m->takeSeat(1, "Bob", "b", kToken1, publicKeyOf("b")).accepted());
  return m;
}

/// A firm break straight up the table from the cue ball's spot, by seat 0, signed (a test that
/// changes a field signs it again with sealed()).
inline protocol::ShotRequest breakShot(std::uint32_t seq = 1) {
  protocol::ShotRequest r;
  r.match = "srv-1";
  r.seat = 0;
  r.seat_token = kToken0;
  r.seq = seq;
  r.cue.yaw = 0.0;
  r.cue.speed = 8.0;
  r.cue.tip_height = 0.1;
  return sealed(r);
}

/// Runs the shot in motion to its end (taking every frame) and returns its report.
inline std::optional<ShotReport> finishNow(Match& match, double now = 1e6) {
  match.takeDueFrames(now);
  return match.finishShot();
}

}  // namespace pool::server::test
