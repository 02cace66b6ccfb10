// A client's join request (take a seat, watch, rejoin, leave, rematch, concede) in domain terms,
// and the signed form of those that change a seat: the envelope with tag SeatRequest.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "protocol/envelope.h"
#include "protocol/key_pair.h"
#include "protocol/match_settings.h"
#include "protocol/protocol_enums.h"
#include "protocol/tournament_view.h"

namespace pool::protocol {

/// The match id that asks for a new match.
inline constexpr const char* kNewMatch = "new";

/// The words of a match state's last verdict after a concession: "seat N" + these (+ what
/// follows: the next rack, or the match won). Clients tell a concession by them.
inline constexpr const char* kConcededTheRack = " conceded the rack";

/// How a tournament a player opens is played (JoinAction::Enter with kNewMatch; its game and race
/// are the request's settings).
struct TournamentOpening {
  TournamentFormat format = TournamentFormat::SingleElimination;
  int entrants = 8;       ///< 3..kMaxTournamentEntrants
  bool handicap = false;  ///< racks on the wire for the lower-rated player of each match
  bool operator==(const TournamentOpening&) const = default;
};

/// One JoinRequest. Every action but Spectate (and Leave by a spectator) changes a seat and must
/// be signed: Seat by the key it binds, the others by the seat's bound key.
struct SeatRequest {
  std::string client;                    ///< the client's id
  std::uint32_t request = 0;             ///< echoed in the answer
  std::uint32_t protocol_version = 0;    ///< the sender's protocol version
  std::string match;                     ///< a match id, or kNewMatch
  JoinAction action = JoinAction::Seat;  ///< what is asked
  int seat = -1;                         ///< 0, 1, or -1 (Seat: any free one; else: the key's)
  std::string name;                      ///< the player's name (Seat)
  std::uint64_t token = 0;               ///< the seat holding's token, 0 when unknown
  std::vector<std::uint8_t> public_key;  ///< the signer's Ed25519 public key (32 bytes)
  std::uint32_t seq = 0;                 ///< per key, strictly increasing
  std::vector<std::uint8_t> signature;   ///< 64 bytes, empty when unsigned
  /// Seat: how to play, if this request opens the table (the first player to sit at a free
  /// table sets them; otherwise they are ignored). Empty: the server's defaults.
  std::optional<MatchSettings> settings;
  /// Enter with kNewMatch (and settings): the tournament to open, which the signer enters first.
  std::optional<TournamentOpening> opening;
};

/// True for the requests that change a seat and so must be signed.
bool changesSeat(const SeatRequest& request);

/// The bytes a seat request's signature covers: the envelope header (tag SeatRequest, match,
/// seat, token, seq), then action u8 | client length u8 + 40 | request u32 | name length u8 + 32
/// | public key 32 bytes (zero-padded) | settings given u8 | game number u8 | race u32 | breaks u8
/// | shot clock f64 | practice u8 (all 0 without settings) | points u32 | opening given u8 | format
/// u8 | entrants u8 | handicap u8 (all 0 without an opening).
std::vector<std::uint8_t> signedBytes(const SeatRequest& request);

/// Fills in `request.public_key` with `key`'s public half and `request.signature` with its
/// signature of signedBytes(request).
void signSeatRequest(SeatRequest& request, const KeyPair& key);

/// Checks `request`'s signature against `public_key`.
SignatureCheck verifySeatRequest(const SeatRequest& request,
                                 std::span<const std::uint8_t> public_key);

}  // namespace pool::protocol
