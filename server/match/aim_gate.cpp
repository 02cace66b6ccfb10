// The aim checks in their order, the per-turn sequence and the per-seat rate window.
#include "server/match/aim_gate.h"

namespace pool::server {

const char* toString(AimDrop drop) {
  switch (drop) {
    case AimDrop::None:
      return "relayed";
    case AimDrop::Malformed:
      return "malformed";
    case AimDrop::NoSuchMatch:
      return "no such match";
    case AimDrop::NotAiming:
      return "nobody is aiming";
    case AimDrop::NotShooter:
      return "not the shooter";
    case AimDrop::BadToken:
      return "bad token";
    case AimDrop::OtherTurn:
      return "another turn";
    case AimDrop::Stale:
      return "stale sequence";
    case AimDrop::Flood:
      return "too many";
    case AimDrop::BadSignature:
      return "bad signature";
    case AimDrop::Count:
      break;
  }
  return "?";
}

AimDrop AimGate::check(const protocol::AimSample& aim, const AimTurn* turn, double now) {
  if (!protocol::checkAim(aim, protocol::CommandLimits{})) {
    return count(AimDrop::Malformed);
  }
  if (!turn) return count(AimDrop::NoSuchMatch);
  if (!turn->aiming) return count(AimDrop::NotAiming);
  if (aim.seat != turn->shooter || turn->banned) return count(AimDrop::NotShooter);
  if (aim.seat_token == 0 || aim.seat_token != turn->token) return count(AimDrop::BadToken);
  if (aim.shot_number != turn->shot_number) return count(AimDrop::OtherTurn);
  SeatTrack& track = seats_[{aim.match, aim.seat}];
  if (track.token != turn->token || track.shot_number != turn->shot_number) {
    track = SeatTrack{turn->token, turn->shot_number, 0, track.window_start, track.in_window};
  }
  if (aim.seq <= track.last_seq) return count(AimDrop::Stale);
  if (now - track.window_start >= 1.0 || now < track.window_start) {
    track.window_start = now;
    track.in_window = 0;
  }
  if (track.in_window >= rates_.per_second) return count(AimDrop::Flood);
  ++track.in_window;
  if (protocol::verifyAim(aim, turn->public_key) != protocol::SignatureCheck::Valid) {
    return count(AimDrop::BadSignature);
  }
  track.last_seq = aim.seq;
  return count(AimDrop::None);
}

void AimGate::forget(const std::string& match) {
  seats_.erase({match, 0});
  seats_.erase({match, 1});
}

}  // namespace pool::server
