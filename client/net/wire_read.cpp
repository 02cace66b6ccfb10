// Wire samples to client domain types: enums range-checked, strings bounded, balls and events
// through common/net's conversions.
#include "client/net/wire_read.h"

#include <string_view>

#include "net/convert.h"
#include "net/wire_fields.h"

namespace pool::client {
namespace {

// The domain enums copy the IDL's enumerators in order; these catch a change on either side.
static_assert(pool_PHASE_CLOSED == static_cast<int>(MatchPhase::Closed));
static_assert(pool_JOIN_REMATCH == static_cast<int>(JoinAction::Rematch));
static_assert(pool_JOIN_STALE_SEQUENCE == static_cast<int>(JoinOutcome::StaleSequence));
static_assert(pool_REJECT_BAD_SIGNATURE == static_cast<int>(RejectReason::BadSignature));
static_assert(pool_REJECT_UNSIGNED == static_cast<int>(RejectReason::Unsigned));
static_assert(pool_END_FORFEIT == static_cast<int>(rules::GameEnd::Forfeit));
static_assert(pool_IN_HAND_BEHIND_HEAD_STRING ==
              static_cast<int>(rules::BallInHand::BehindHeadString));
static_assert(pool_GROUP_STRIPES == static_cast<int>(rules::Group::Stripes));
static_assert(pool_FOUL_BEHIND_HEAD_STRING_DIRECT ==
              static_cast<int>(rules::Foul::BehindHeadStringDirect));
static_assert(pool_OPTION_OPPONENT_REBREAKS - pool_OPTION_PLAY_ON ==
              static_cast<int>(rules::Choice::OpponentReBreaks));

// An IDL enum field as a domain enum whose enumerators follow the IDL's order one to one, or
// empty when the value is out of range.
template <class Domain, class Wire>
std::optional<Domain> enumOf(const Wire& field, std::int32_t count) {
  const std::int32_t raw = net::rawValue(field);
  if (raw < 0 || raw >= count) return std::nullopt;
  return static_cast<Domain>(raw);
}

template <class T>
Result<T> fail(std::string_view what, std::string_view why) {
  return Result<T>::fail(std::string(what) + ": " + std::string(why));
}

// ShotOption values other than OPTION_NONE, as the rules' choices.
Result<std::vector<rules::Choice>> choicesOf(const dds_sequence_pool_ShotOption& seq) {
  std::vector<rules::Choice> out;
  for (const auto& option : net::elementsOf(seq)) {
    const auto raw = net::rawValue(option);
    if (raw == pool_OPTION_NONE) continue;
    if (raw < pool_OPTION_PLAY_ON || raw > pool_OPTION_OPPONENT_REBREAKS) {
      return Result<std::vector<rules::Choice>>::fail("unknown option " + std::to_string(raw));
    }
    out.push_back(static_cast<rules::Choice>(raw - pool_OPTION_PLAY_ON));
  }
  return Result<std::vector<rules::Choice>>::ok(std::move(out));
}

Result<std::vector<rules::Foul>> foulsOf(const dds_sequence_pool_FoulCode& seq) {
  std::vector<rules::Foul> out;
  for (const auto& code : net::elementsOf(seq)) {
    const auto foul = enumOf<rules::Foul>(code, pool_FOUL_BEHIND_HEAD_STRING_DIRECT + 1);
    if (!foul) return Result<std::vector<rules::Foul>>::fail("unknown foul");
    out.push_back(*foul);
  }
  return Result<std::vector<rules::Foul>>::ok(std::move(out));
}

std::optional<SeatView> seatOf(const pool_SeatState& seat) {
  SeatView view;
  view.name = std::string(net::textOf(seat.name));
  view.connected = seat.connected;
  const auto group = enumOf<rules::Group>(seat.group, pool_GROUP_STRIPES + 1);
  if (!group) return std::nullopt;
  view.group = *group;
  view.balls_left = seat.balls_left;
  view.fouls = seat.fouls;
  view.racks_won = seat.racks_won;
  return view;
}

int seatNumber(std::int16_t seat) {
  return seat == 0 || seat == 1 ? seat : -1;
}

}  // namespace

Result<LobbyEntry> fromWire(const pool_MatchInfo& info) {
  LobbyEntry entry;
  entry.match = std::string(net::textOf(info.match));
  entry.server = std::string(net::textOf(info.server));
  entry.name = std::string(net::textOf(info.name));
  entry.table = std::string(net::textOf(info.table));
  const auto phase = enumOf<MatchPhase>(info.phase, pool_PHASE_CLOSED + 1);
  if (!phase) return fail<LobbyEntry>("match info " + entry.match, "unknown phase");
  entry.phase = *phase;
  for (std::size_t i = 0; i < 2; ++i) entry.players[i] = std::string(net::textOf(info.players[i]));
  entry.seats_taken = info.seats_taken;
  entry.spectators = info.spectators;
  entry.protocol_version = info.protocol_version;
  return Result<LobbyEntry>::ok(std::move(entry));
}

Result<JoinAnswer> fromWire(const pool_JoinReply& reply) {
  JoinAnswer answer;
  answer.request = reply.request;
  answer.server = std::string(net::textOf(reply.server));
  answer.match = std::string(net::textOf(reply.match));
  const auto action = enumOf<JoinAction>(reply.action, pool_JOIN_REMATCH + 1);
  const auto outcome = enumOf<JoinOutcome>(reply.outcome, pool_JOIN_STALE_SEQUENCE + 1);
  if (!action || !outcome) return fail<JoinAnswer>("join reply", "unknown action or outcome");
  answer.action = *action;
  answer.outcome = *outcome;
  answer.reason = std::string(net::textOf(reply.reason));
  answer.seat = seatNumber(reply.seat);
  answer.token = reply.seat_token;
  answer.last_seq = reply.last_seq;
  return Result<JoinAnswer>::ok(std::move(answer));
}

Result<MatchView> fromWire(const pool_MatchState& state) {
  MatchView view;
  view.match = std::string(net::textOf(state.match));
  const std::string what = "match state " + view.match;
  view.revision = state.revision;
  const auto phase = enumOf<MatchPhase>(state.phase, pool_PHASE_CLOSED + 1);
  const auto in_hand =
      enumOf<rules::BallInHand>(state.ball_in_hand, pool_IN_HAND_BEHIND_HEAD_STRING + 1);
  const auto end = enumOf<rules::GameEnd>(state.end, pool_END_FORFEIT + 1);
  if (!phase || !in_hand || !end) return fail<MatchView>(what, "unknown enum value");
  view.phase = *phase;
  view.ball_in_hand = *in_hand;
  view.end = *end;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto seat = seatOf(state.seats[i]);
    if (!seat) return fail<MatchView>(what, "unknown group");
    view.seats[i] = *seat;
    view.seats[i].last_seq = state.seat_seq[i];
  }
  view.shooter = seatNumber(state.shooter);
  view.breaker = seatNumber(state.breaker);
  view.rack = state.rack;
  view.shot_number = state.shot_number;
  auto options = choicesOf(state.options);
  if (!options) return fail<MatchView>(what, options.error());
  view.options = std::move(*options);
  view.shot_clock = state.shot_clock;
  view.winner = seatNumber(state.winner);
  view.last_verdict = std::string(net::textOf(state.last_verdict));
  auto balls = net::getBalls(state.balls);
  if (!balls) return fail<MatchView>(what, balls.error());
  view.balls = std::move(*balls);
  return Result<MatchView>::ok(std::move(view));
}

Result<ShotReport> fromWire(const pool_ShotResult& result) {
  ShotReport report;
  report.match = std::string(net::textOf(result.match));
  const std::string what = "shot result " + report.match;
  report.seat = seatNumber(result.seat);
  report.seq = result.seq;
  report.shot_number = result.shot_number;
  report.accepted = result.accepted;
  const auto reason = enumOf<RejectReason>(result.reject_reason, pool_REJECT_UNSIGNED + 1);
  const auto in_hand =
      enumOf<rules::BallInHand>(result.ball_in_hand, pool_IN_HAND_BEHIND_HEAD_STRING + 1);
  const auto end = enumOf<rules::GameEnd>(result.end, pool_END_FORFEIT + 1);
  if (!reason || !in_hand || !end) return fail<ShotReport>(what, "unknown enum value");
  report.reject_reason = *reason;
  report.ball_in_hand = *in_hand;
  report.end = *end;
  report.reject_text = std::string(net::textOf(result.reject_text));
  auto events = net::getEvents(result.events);
  auto fouls = foulsOf(result.fouls);
  auto options = choicesOf(result.options);
  if (!events) return fail<ShotReport>(what, events.error());
  if (!fouls) return fail<ShotReport>(what, fouls.error());
  if (!options) return fail<ShotReport>(what, options.error());
  report.events = std::move(*events);
  report.fouls = std::move(*fouls);
  report.options = std::move(*options);
  for (auto id : net::elementsOf(result.pocketed)) report.pocketed.push_back(id);
  report.turn_continues = result.turn_continues;
  report.next_shooter = seatNumber(result.next_shooter);
  report.game_over = result.game_over;
  report.winner = seatNumber(result.winner);
  report.verdict_text = std::string(net::textOf(result.verdict_text));
  return Result<ShotReport>::ok(std::move(report));
}

Result<TableFrame> fromWire(const pool_TableSnapshot& snapshot) {
  TableFrame frame;
  frame.match = std::string(net::textOf(snapshot.match));
  frame.frame = snapshot.frame;
  frame.sim_time = snapshot.sim_time;
  frame.shot_number = snapshot.shot_number;
  auto balls = net::getBalls(snapshot.balls);
  if (!balls) return fail<TableFrame>("snapshot " + frame.match, balls.error());
  frame.balls = std::move(*balls);
  return Result<TableFrame>::ok(std::move(frame));
}

net::Sample<pool_JoinRequest> toWire(const protocol::SeatRequest& fields) {
  net::Sample<pool_JoinRequest> sample;
  pool_JoinRequest& request = *sample;
  net::setText(request.client, fields.client);
  request.request = fields.request;
  request.protocol_version = fields.protocol_version;
  net::setText(request.match, fields.match);
  request.action = static_cast<pool_JoinAction>(static_cast<int>(fields.action));
  request.seat = static_cast<std::int16_t>(fields.seat);
  net::setText(request.name, fields.name);
  request.seat_token = fields.token;
  net::setBytes(request.public_key, fields.public_key, protocol::kPublicKeyBytes);
  request.seq = fields.seq;
  net::setBytes(request.signature, fields.signature, protocol::kSignatureBytes);
  return sample;
}

}  // namespace pool::client
