// Field by field between protocol::AimSample and pool_AimCommand / pool_CueAim.
#include "net/aim_convert.h"

#include "net/wire_fields.h"

namespace pool::net {
namespace {

/// The cue's values, common to both wire types.
template <class Wire>
void putValues(Wire& w, const protocol::AimSample& a) {
  setText(w.match, a.match);
  w.seat = static_cast<std::int16_t>(a.seat);
  w.seq = a.seq;
  w.shot_number = a.shot_number;
  w.yaw = a.yaw;
  w.tip_side = a.tip_side;
  w.tip_height = a.tip_height;
  w.elevation = a.elevation;
  w.power = a.power;
  w.stroke = a.stroke;
  w.cue_ball_x = a.cue_ball_x;
  w.cue_ball_y = a.cue_ball_y;
}

template <class Wire>
Result<protocol::AimSample> getValues(const Wire& w, const char* what) {
  if (!terminated(w.match)) {
    return Result<protocol::AimSample>::fail(std::string(what) + ": match id past its bound");
  }
  protocol::AimSample a;
  a.match = std::string(textOf(w.match));
  a.seat = w.seat;
  a.seq = w.seq;
  a.shot_number = w.shot_number;
  a.yaw = w.yaw;
  a.tip_side = w.tip_side;
  a.tip_height = w.tip_height;
  a.elevation = w.elevation;
  a.power = w.power;
  a.stroke = w.stroke;
  a.cue_ball_x = w.cue_ball_x;
  a.cue_ball_y = w.cue_ball_y;
  return Result<protocol::AimSample>::ok(std::move(a));
}

}  // namespace

Sample<pool_AimCommand> toAimCommand(const protocol::AimSample& aim) {
  Sample<pool_AimCommand> sample;
  putValues(*sample, aim);
  sample->seat_token = aim.seat_token;
  setBytes(sample->signature, aim.signature, protocol::kSignatureBytes);
  return sample;
}

Sample<pool_CueAim> toCueAim(const protocol::AimSample& aim) {
  Sample<pool_CueAim> sample;
  putValues(*sample, aim);
  return sample;
}

Result<protocol::AimSample> fromWire(const pool_AimCommand& command) {
  auto aim = getValues(command, "aim command");
  if (!aim) return aim;
  const auto signature = elementsOf(command.signature);
  if (signature.size() > protocol::kSignatureBytes) {
    return Result<protocol::AimSample>::fail("aim command: signature longer than 64 bytes");
  }
  aim->seat_token = command.seat_token;
  aim->signature.assign(signature.begin(), signature.end());
  return aim;
}

Result<protocol::AimSample> fromWire(const pool_CueAim& wire) {
  auto aim = getValues(wire, "cue aim");
  if (!aim) return aim;
  if (auto ok = protocol::checkAim(*aim, protocol::CommandLimits{}); !ok) {
    return Result<protocol::AimSample>::fail("cue aim of " + aim->match + ": " + ok.error());
  }
  return aim;
}

}  // namespace pool::net
