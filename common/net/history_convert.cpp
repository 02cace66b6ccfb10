// Field by field between the replay messages (protocol/history.h) and their wire types.
#include "net/history_convert.h"

#include "net/convert.h"
#include "net/wire_fields.h"

namespace pool::net {

static_assert(pool_MAX_HISTORY_SHOTS == protocol::kMaxHistoryShots);

Sample<pool_HistoryRequest> toWire(const protocol::HistoryRequest& r) {
  Sample<pool_HistoryRequest> sample;
  pool_HistoryRequest& w = *sample;
  setText(w.client, r.client);
  w.request = r.request;
  setText(w.match, r.match);
  w.first_shot = r.first_shot;
  w.count = static_cast<std::uint8_t>(std::min<std::uint32_t>(r.count, 255));
  setBytes(w.public_key, r.public_key, 32);
  setBytes(w.signature, r.signature, 64);
  return sample;
}

Result<protocol::HistoryRequest> fromWire(const pool_HistoryRequest& w) {
  using Out = Result<protocol::HistoryRequest>;
  if (!terminated(w.client) || !terminated(w.match)) {
    return Out::fail("history request: a text past its bound");
  }
  if (w.public_key._length != 32 || !w.public_key._buffer) {
    return Out::fail("history request: public_key is not 32 bytes");
  }
  if (w.signature._length > 64 || (w.signature._length > 0 && !w.signature._buffer)) {
    return Out::fail("history request: signature past 64 bytes");
  }
  protocol::HistoryRequest r;
  r.client = std::string(textOf(w.client));
  r.request = w.request;
  r.match = std::string(textOf(w.match));
  r.first_shot = w.first_shot;
  r.count = w.count;
  const auto key = elementsOf(w.public_key);
  r.public_key.assign(key.begin(), key.end());
  const auto signature = elementsOf(w.signature);
  r.signature.assign(signature.begin(), signature.end());
  return Out::ok(std::move(r));
}

Sample<pool_HistoryShot> toWire(const protocol::HistoryShot& s) {
  Sample<pool_HistoryShot> sample;
  pool_HistoryShot& w = *sample;
  setText(w.client, s.client);
  w.request = s.request;
  setBytes(w.asker, s.asker, 32);
  setText(w.match, s.match);
  w.found = s.found;
  setText(w.error, s.error);
  w.shot_number = s.shot_number;
  w.shots = s.shots;
  w.game = static_cast<std::uint8_t>(rules::gameNumber(s.game));
  setText(w.table, s.table);
  for (std::size_t i = 0; i < 2; ++i) setText(w.players[i], s.players[i]);
  w.seat = static_cast<std::int16_t>(s.seat);
  w.yaw = s.cue.yaw;
  w.tip_side = s.cue.tip_side;
  w.tip_height = s.cue.tip_height;
  w.elevation = s.cue.elevation;
  w.speed = s.cue.speed;
  w.cue_ball = static_cast<std::uint8_t>(s.cue.ball);
  w.shoots = s.shoots;
  putBalls(w.before, s.before);
  putEvents(w.events, s.events);
  putBalls(w.after, s.after);
  setText(w.verdict_text, s.verdict_text);
  return sample;
}

Result<protocol::HistoryShot> fromWire(const pool_HistoryShot& w) {
  using Out = Result<protocol::HistoryShot>;
  if (!terminated(w.client) || !terminated(w.match) || !terminated(w.error) ||
      !terminated(w.table) || !terminated(w.players[0]) || !terminated(w.players[1]) ||
      !terminated(w.verdict_text)) {
    return Out::fail("history shot: a text past its bound");
  }
  protocol::HistoryShot s;
  s.client = std::string(textOf(w.client));
  s.request = w.request;
  if (w.asker._length > 32 || (w.asker._length > 0 && !w.asker._buffer)) {
    return Out::fail("history shot: asker past 32 bytes");
  }
  const auto asker = elementsOf(w.asker);
  s.asker.assign(asker.begin(), asker.end());
  s.match = std::string(textOf(w.match));
  s.found = w.found;
  s.error = std::string(textOf(w.error));
  if (!s.found) return Out::ok(std::move(s));
  s.shot_number = w.shot_number;
  s.shots = w.shots;
  const auto game = rules::gameOfNumber(w.game);
  if (!game) return Out::fail("history shot: unknown game " + std::to_string(w.game));
  s.game = *game;
  s.table = std::string(textOf(w.table));
  for (std::size_t i = 0; i < 2; ++i) s.players[i] = std::string(textOf(w.players[i]));
  s.seat = w.seat;
  s.cue.yaw = w.yaw;
  s.cue.tip_side = w.tip_side;
  s.cue.tip_height = w.tip_height;
  s.cue.elevation = w.elevation;
  s.cue.speed = w.speed;
  s.cue.ball = w.cue_ball;
  s.shoots = w.shoots;
  auto before = getBalls(w.before);
  if (!before) return Out::fail("history shot: before " + before.error());
  auto events = getEvents(w.events);
  if (!events) return Out::fail("history shot: " + events.error());
  auto after = getBalls(w.after);
  if (!after) return Out::fail("history shot: after " + after.error());
  s.before = std::move(*before);
  s.events = std::move(*events);
  s.after = std::move(*after);
  s.verdict_text = std::string(textOf(w.verdict_text));
  return Out::ok(std::move(s));
}

}  // namespace pool::net
