// Replays: a request for a match's stored shots (signed by the asker's key in the envelope with
// tag History) and one stored shot as the server answers it.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "core/check.h"
#include "physics/ball.h"
#include "physics/cue_strike.h"
#include "physics/events.h"
#include "protocol/envelope.h"
#include "protocol/key_pair.h"
#include "rules/game_rules.h"

namespace pool::protocol {

/// The most stored shots one request may ask for (pool.idl's MAX_HISTORY_SHOTS).
inline constexpr std::uint32_t kMaxHistoryShots = 4;

/// A request for shots first_shot .. first_shot + count - 1 of `match`. It changes nothing; its
/// signature (any key's) makes the asker's key the one its share of answers is charged to.
struct HistoryRequest {
  std::string client;  ///< the asker's client id, which the answers name
  std::uint32_t request = 0;
  std::string match;
  std::uint32_t first_shot = 1;
  std::uint32_t count = 1;
  std::vector<std::uint8_t> public_key;  ///< 32 bytes
  std::vector<std::uint8_t> signature;   ///< 64 bytes
};

/// The bytes the asker signs: the envelope header (tag History, match, seat -1, token 0, seq the
/// request number), then first_shot u32 | count u8 | client (length byte + 40).
std::vector<std::uint8_t> signedBytes(const HistoryRequest& request);

/// Fills in `request.public_key` and `request.signature` with `key`'s.
void signHistory(HistoryRequest& request, const KeyPair& key);

/// Checks the request's signature against the key it carries.
SignatureCheck verifyHistory(const HistoryRequest& request);

/// Refuses a request the server does not answer, with why ("<field>: <reason>"): a client id and
/// a match id of 1–40 bytes, first_shot from 1, count 1..kMaxHistoryShots.
Check<> checkHistoryRequest(const HistoryRequest& request);

/// One stored shot, as the server answers a request (or why there is none: `found` false).
struct HistoryShot {
  std::string client;  ///< the request answered
  std::uint32_t request = 0;
  std::vector<std::uint8_t> asker;  ///< the key that signed it (32 bytes)
  std::string match;
  bool found = false;
  std::string error;  ///< why not, when not found
  std::uint32_t shot_number = 0;
  std::uint32_t shots = 0;  ///< stored shots of the match
  rules::Game game = rules::Game::EightBall;
  std::string table;  ///< table spec name
  std::array<std::string, 2> players;
  int seat = 0;  ///< the shooter
  physics::CueShot cue;
  bool shoots = true;  ///< false: a choice that re-racked
  std::vector<physics::Ball> before;
  physics::EventLog events;
  std::vector<physics::Ball> after;
  std::string verdict_text;
};

}  // namespace pool::protocol
