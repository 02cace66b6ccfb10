// The signed encoding of seat requests.
#include "protocol/seat_request.h"

#include <algorithm>

namespace pool::protocol {

namespace {

constexpr std::size_t kClientField = 40;
constexpr std::size_t kNameField = 32;

}  // namespace

bool changesSeat(const SeatRequest& r) {
  switch (r.action) {
    case JoinAction::Spectate:
      return false;
    case JoinAction::Leave:
      return r.token != 0 || r.seat >= 0;  // a spectator's leave names no seat
    case JoinAction::Seat:
    case JoinAction::Rejoin:
    case JoinAction::Rematch:
    case JoinAction::Concede:
    case JoinAction::Enter:  // the entrant is the key that signs
      return true;
  }
  return true;
}

std::vector<std::uint8_t> signedBytes(const SeatRequest& r) {
  SignedEncoder e({MessageTag::SeatRequest, r.match, r.seat, r.token, r.seq});
  e.u8(static_cast<std::uint8_t>(r.action));
  e.text(r.client, kClientField);
  e.u32(r.request);
  e.text(r.name, kNameField);
  e.bytes(r.public_key, kPublicKeyBytes);
  const MatchSettings none{};
  const MatchSettings& s = r.settings ? *r.settings : none;
  e.u8(r.settings ? 1 : 0);
  e.u8(r.settings ? static_cast<std::uint8_t>(rules::gameNumber(s.game)) : 0);
  e.u32(r.settings ? static_cast<std::uint32_t>(s.race_to) : 0);
  e.u8(r.settings ? static_cast<std::uint8_t>(s.breaks) : 0);
  e.f64(r.settings ? s.shot_clock : 0.0);
  e.u8(r.settings && s.practice ? 1 : 0);
  e.u32(r.settings ? static_cast<std::uint32_t>(s.points) : 0);               // since version 7
  const TournamentOpening& o = r.opening ? *r.opening : TournamentOpening{};  // since version 11
  e.u8(r.opening ? 1 : 0);
  e.u8(r.opening ? static_cast<std::uint8_t>(o.format) : 0);
  e.u8(r.opening ? static_cast<std::uint8_t>(std::clamp(o.entrants, 0, 255)) : 0);
  e.u8(r.opening && o.handicap ? 1 : 0);
  return e.message();
}

void signSeatRequest(SeatRequest& request, const KeyPair& key) {
  request.public_key = key.publicKey();
  request.signature = signMessage(signedBytes(request), key);
}

SignatureCheck verifySeatRequest(const SeatRequest& request,
                                 std::span<const std::uint8_t> public_key) {
  if (request.signature.empty()) return SignatureCheck::Unsigned;
  return verifyMessage(signedBytes(request), request.signature, public_key);
}

}  // namespace pool::protocol
