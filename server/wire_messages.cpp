// Filling pool.idl's outgoing messages from the match logic's domain types.
#include "wire_messages.h"

#include <algorithm>

#include "net/convert.h"
#include "net/wire_fields.h"
#include "rules/ball_groups.h"
#include "wire_enums.h"

namespace pool::server {

namespace {

std::uint8_t ballsLeft(const Match& match, rules::Group group) {
  // While the table is open each player has seven to go.
  if (group == rules::Group::None) return 7;
  const auto& balls = match.balls();
  return static_cast<std::uint8_t>(std::count_if(balls.begin(), balls.end(), [&](const auto& b) {
    return physics::onTable(b.state) && rules::groupOf(b.id) == group;
  }));
}

pool_SeatState seatState(const Match& match, int seat) {
  const Seat& s = match.seats()[static_cast<std::size_t>(seat)];
  const rules::Group group = match.game().groups[static_cast<std::size_t>(seat)];
  pool_SeatState out{};
  net::setText(out.name, s.player);
  out.connected = s.connected();
  out.group = toWire(group);
  out.balls_left = ballsLeft(match, group);
  out.fouls = static_cast<std::uint16_t>(s.fouls);
  out.racks_won = static_cast<std::uint16_t>(s.racks_won);
  return out;
}

template <class Seq, class T, class F>
void putAll(Seq& seq, const std::vector<T>& items, F convert) {
  const auto n = static_cast<std::uint32_t>(std::min<std::size_t>(items.size(), 8));
  auto out = net::resizeSequence(seq, n);
  for (std::uint32_t i = 0; i < n; ++i) out[i] = convert(items[i]);
}

}  // namespace

pool_MatchInfo matchInfo(const Match& match, const std::string& server_id) {
  pool_MatchInfo info{};
  net::setText(info.match, match.id());
  net::setText(info.server, server_id);
  net::setText(info.name, match.name());
  net::setText(info.table, match.table().spec.name);
  info.phase = toWire(match.phase());
  for (std::size_t s = 0; s < 2; ++s) {
    const Seat& seat = match.seats()[s];
    net::setText(info.players[s], seat.player);
    info.seats_taken = static_cast<std::uint8_t>(info.seats_taken + (seat.taken() ? 1 : 0));
  }
  info.spectators = static_cast<std::uint32_t>(match.spectators());
  info.protocol_version = protocol::kProtocolVersion;
  return info;
}

net::Sample<pool_MatchState> matchState(const Match& match) {
  net::Sample<pool_MatchState> sample;
  pool_MatchState& st = *sample;
  const rules::GameState& game = match.game();
  const bool started = match.phase() != MatchPhase::Lobby;
  net::setText(st.match, match.id());
  st.revision = static_cast<std::uint32_t>(match.revision());
  st.phase = toWire(match.phase());
  st.seats[0] = seatState(match, 0);
  st.seats[1] = seatState(match, 1);
  st.seat_seq[0] = match.seats()[0].last_seq;
  st.seat_seq[1] = match.seats()[1].last_seq;
  st.shooter = static_cast<std::int16_t>(match.inPlay() ? game.shooter : -1);
  st.breaker = static_cast<std::int16_t>(started ? game.breaker : -1);
  st.rack = match.rack();
  st.shot_number = match.shotNumber();
  st.ball_in_hand = toWire(match.inPlay() ? game.ball_in_hand : rules::BallInHand::None);
  putAll(st.options, game.options, [](rules::Choice c) { return toWire(c); });
  st.shot_clock = -1.0;  // no shot clock yet
  st.winner = static_cast<std::int16_t>(game.winner);
  st.end = toWire(game.end);
  net::setText(st.last_verdict, match.lastVerdict());
  net::putBalls(st.balls, match.balls());
  return sample;
}

net::Sample<pool_ShotResult> commandResult(const std::string& match, const CommandAnswer& answer) {
  net::Sample<pool_ShotResult> sample;
  pool_ShotResult& r = *sample;
  net::setText(r.match, match);
  r.seat = static_cast<std::int16_t>(answer.seat);
  r.seq = answer.seq;
  r.shot_number = answer.shot_number;
  r.accepted = answer.accepted();
  r.reject_reason = toWire(answer.rejection.reason);
  net::setText(r.reject_text, answer.rejection.text);
  r.next_shooter = -1;
  r.winner = -1;
  return sample;
}

net::Sample<pool_ShotResult> finalResult(const std::string& match, const ShotReport& report) {
  net::Sample<pool_ShotResult> sample;
  pool_ShotResult& r = *sample;
  const rules::Verdict& v = report.verdict;
  net::setText(r.match, match);
  r.seat = static_cast<std::int16_t>(report.seat);
  r.seq = report.seq;
  r.shot_number = report.shot_number;
  r.accepted = true;
  r.reject_reason = pool_REJECT_NONE;
  net::putEvents(r.events, report.events);
  putAll(r.fouls, v.fouls, [](rules::Foul f) { return toWire(f); });
  const auto pocketed = net::resizeSequence(
      r.pocketed, static_cast<std::uint32_t>(std::min<std::size_t>(v.pocketed.size(), 16)));
  for (std::size_t i = 0; i < pocketed.size(); ++i) {
    pocketed[i] = static_cast<std::uint8_t>(v.pocketed[i]);
  }
  r.turn_continues = v.turn_continues;
  r.next_shooter = static_cast<std::int16_t>(v.next_shooter);
  r.ball_in_hand = toWire(v.ball_in_hand);
  putAll(r.options, v.options, [](rules::Choice c) { return toWire(c); });
  r.game_over = v.game_over;
  r.winner = static_cast<std::int16_t>(v.winner);
  r.end = toWire(v.end);
  net::setText(r.verdict_text, rules::describe(v));
  return sample;
}

net::Sample<pool_TableSnapshot> snapshot(const std::string& match, std::uint32_t frame,
                                         std::uint32_t shot_number, const physics::Sample& at) {
  net::Sample<pool_TableSnapshot> sample;
  net::setText(sample->match, match);
  sample->frame = frame;
  sample->sim_time = at.t;
  sample->shot_number = shot_number;
  net::putBalls(sample->balls, at.balls);
  return sample;
}

pool_JoinReply joinReply(const JoinCommand& command, const JoinAnswer& answer,
                         const std::string& server_id) {
  pool_JoinReply reply{};
  net::setText(reply.client, command.client);
  reply.request = command.request;
  net::setText(reply.server, server_id);
  net::setText(reply.match, answer.match.empty() ? command.match : answer.match);
  reply.action = toWire(command.action);
  reply.outcome = toWire(answer.outcome);
  net::setText(reply.reason, answer.reason);
  reply.seat = static_cast<std::int16_t>(answer.seat);
  reply.seat_token = answer.token;
  reply.last_seq = answer.last_seq;
  return reply;
}

}  // namespace pool::server
