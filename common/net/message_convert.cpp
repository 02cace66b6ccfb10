// The protocol's messages to and from their wire samples: enums range-checked on the way in,
// strings bounded, balls and events through convert.h.
#include "net/message_convert.h"

#include <algorithm>
#include <string_view>

#include "net/convert.h"
#include "net/wire_fields.h"

namespace pool::net {
namespace {

using namespace protocol;

// The domain enums copy the IDL's enumerators in order; these catch a change on either side.
static_assert(pool_PHASE_CLOSED == static_cast<int>(MatchPhase::Closed));
static_assert(pool_JOIN_ENTER == static_cast<int>(JoinAction::Enter));
static_assert(pool_JOIN_STALE_SEQUENCE == static_cast<int>(JoinOutcome::StaleSequence));
// Every refusal reason, one by one: an earlier order of the domain enum differed from the IDL's.
static_assert(pool_REJECT_MALFORMED == static_cast<int>(RejectReason::Malformed));
static_assert(pool_REJECT_NO_SUCH_MATCH == static_cast<int>(RejectReason::NoSuchMatch));
static_assert(pool_REJECT_WRONG_SEAT == static_cast<int>(RejectReason::WrongSeat));
static_assert(pool_REJECT_BAD_TOKEN == static_cast<int>(RejectReason::BadToken));
static_assert(pool_REJECT_NOT_YOUR_TURN == static_cast<int>(RejectReason::NotYourTurn));
static_assert(pool_REJECT_BALLS_MOVING == static_cast<int>(RejectReason::BallsMoving));
static_assert(pool_REJECT_STALE_SEQUENCE == static_cast<int>(RejectReason::StaleSequence));
static_assert(pool_REJECT_ILLEGAL_PLACEMENT == static_cast<int>(RejectReason::IllegalPlacement));
static_assert(pool_REJECT_OPTION_REQUIRED == static_cast<int>(RejectReason::OptionRequired));
static_assert(pool_REJECT_OPTION_NOT_OFFERED == static_cast<int>(RejectReason::OptionNotOffered));
static_assert(pool_REJECT_BAD_CALL == static_cast<int>(RejectReason::BadCall));
static_assert(pool_REJECT_MATCH_OVER == static_cast<int>(RejectReason::MatchOver));
static_assert(pool_REJECT_BAD_SIGNATURE == static_cast<int>(RejectReason::BadSignature));
static_assert(pool_REJECT_UNSIGNED == static_cast<int>(RejectReason::Unsigned));
static_assert(pool_REJECT_BAD_PRACTICE == static_cast<int>(RejectReason::BadPractice));
static_assert(pool_END_THREE_FOULS == static_cast<int>(rules::GameEnd::ThreeFouls));
static_assert(pool_END_POINTS_REACHED == static_cast<int>(rules::GameEnd::PointsReached));
static_assert(pool_END_THREE_MISSES == static_cast<int>(rules::GameEnd::ThreeMisses));
static_assert(pool_IN_HAND_IN_THE_D == static_cast<int>(rules::BallInHand::InTheD));
static_assert(pool_GROUP_STRIPES == static_cast<int>(rules::Group::Stripes));
static_assert(pool_FOUL_FREE_BALL_SNOOKERS == static_cast<int>(rules::Foul::FreeBallSnookers));
static_assert(pool_OPTION_REPLACE - pool_OPTION_PLAY_ON ==
              static_cast<int>(rules::Choice::Replace));

// An IDL enum field as a domain enum whose enumerators follow the IDL's order one to one, or
// empty when the value is out of range.
template <class Domain, class Wire>
std::optional<Domain> enumOf(const Wire& field, std::int32_t count) {
  const std::int32_t raw = rawValue(field);
  if (raw < 0 || raw >= count) return std::nullopt;
  return static_cast<Domain>(raw);
}

template <class T>
Result<T> fail(std::string_view what, std::string_view why) {
  return Result<T>::fail(std::string(what) + ": " + std::string(why));
}

/// Fills a sequence with at most 8 converted items (the bound of every enum sequence here).
template <class Seq, class T, class F>
void putAll(Seq& seq, const std::vector<T>& items, F convert) {
  const auto n = static_cast<std::uint32_t>(std::min<std::size_t>(items.size(), 8));
  auto out = resizeSequence(seq, n);
  for (std::uint32_t i = 0; i < n; ++i) out[i] = convert(items[i]);
}

/// A domain enum whose enumerators follow the IDL's one to one, as the IDL's.
template <class Wire, class Domain>
Wire wireOf(Domain value) {
  return static_cast<Wire>(static_cast<int>(value));
}

// The rules' choice on the wire: the protocol's option for it (protocol::optionOf), as the IDL's.
pool_ShotOption wireChoice(rules::Choice c) {
  return net::toWire(protocol::optionOf(c));
}

pool_SeatState seatStateOf(const SeatView& seat) {
  pool_SeatState out{};
  setText(out.name, seat.name);
  out.connected = seat.connected;
  out.group = wireOf<pool_BallGroup>(seat.group);
  out.balls_left = static_cast<std::uint8_t>(seat.balls_left);
  out.fouls = static_cast<std::uint16_t>(seat.fouls);
  out.racks_won = static_cast<std::uint16_t>(seat.racks_won);
  return out;
}

// ShotOption values other than OPTION_NONE, as the rules' choices (protocol::choiceOf).
Result<std::vector<rules::Choice>> choicesOf(const dds_sequence_pool_ShotOption& seq) {
  std::vector<rules::Choice> out;
  for (const auto& option : elementsOf(seq)) {
    const auto domain = net::fromWire(option);
    if (!domain) return Result<std::vector<rules::Choice>>::fail(domain.error());
    if (const auto choice = protocol::choiceOf(*domain)) out.push_back(*choice);
  }
  return Result<std::vector<rules::Choice>>::ok(std::move(out));
}

Result<std::vector<rules::Foul>> foulsOf(const dds_sequence_pool_FoulCode& seq) {
  std::vector<rules::Foul> out;
  for (const auto& code : elementsOf(seq)) {
    const auto foul = enumOf<rules::Foul>(code, pool_FOUL_FREE_BALL_SNOOKERS + 1);
    if (!foul) return Result<std::vector<rules::Foul>>::fail("unknown foul");
    out.push_back(*foul);
  }
  return Result<std::vector<rules::Foul>>::ok(std::move(out));
}

std::optional<SeatView> seatOf(const pool_SeatState& seat) {
  SeatView view;
  view.name = std::string(textOf(seat.name));
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

static_assert(pool_BREAK_WINNER == static_cast<int>(BreakOrder::Winner));

// Settings from their wire fields, checked as the server checks a table's settings.
Result<MatchSettings> settingsOf(std::uint8_t game, std::uint16_t race_to,
                                 const pool_BreakOrder& breaks, double shot_clock, bool practice,
                                 std::uint16_t points) {
  MatchSettings s;
  const auto g = rules::gameOfNumber(game);
  const auto order = enumOf<BreakOrder>(breaks, pool_BREAK_WINNER + 1);
  if (!g) return Result<MatchSettings>::fail("game: must be 8, 9, 10 or 3 (three-cushion)");
  if (!order) return Result<MatchSettings>::fail("breaks: not a known break order");
  s.game = *g;
  s.race_to = race_to;
  s.breaks = *order;
  s.shot_clock = shot_clock;
  s.practice = practice;
  // Only three-cushion has points; any other game keeps the default whatever the field says.
  s.points = s.game == rules::Game::ThreeCushion ? points : kDefaultPoints;
  if (auto why = checkSettings(s); !why) return Result<MatchSettings>::fail(why.error());
  return Result<MatchSettings>::ok(s);
}

}  // namespace

Result<LobbyEntry> fromWire(const pool_MatchInfo& info) {
  LobbyEntry entry;
  entry.match = std::string(textOf(info.match));
  entry.server = std::string(textOf(info.server));
  entry.name = std::string(textOf(info.name));
  entry.table = std::string(textOf(info.table));
  const auto phase = enumOf<MatchPhase>(info.phase, pool_PHASE_CLOSED + 1);
  if (!phase) return fail<LobbyEntry>("match info " + entry.match, "unknown phase");
  entry.phase = *phase;
  for (std::size_t i = 0; i < 2; ++i) entry.players[i] = std::string(textOf(info.players[i]));
  entry.seats_taken = info.seats_taken;
  entry.spectators = info.spectators;
  auto settings = settingsOf(info.game, info.race_to, info.breaks, info.shot_clock_limit,
                             info.practice, info.points);
  if (!settings) return fail<LobbyEntry>("match info " + entry.match, settings.error());
  entry.settings = *settings;
  entry.racks_won = {info.racks_won[0], info.racks_won[1]};
  entry.ratings = {info.ratings[0], info.ratings[1]};
  entry.rack = info.rack;
  entry.shot_number = info.shot_number;
  entry.rack_points = {info.rack_points[0], info.rack_points[1]};
  entry.standard_physics = info.standard_physics;
  entry.protocol_version = info.protocol_version;
  return Result<LobbyEntry>::ok(std::move(entry));
}

Result<JoinAnswer> fromWire(const pool_JoinReply& reply) {
  JoinAnswer answer;
  answer.client = std::string(textOf(reply.client));
  answer.request = reply.request;
  answer.server = std::string(textOf(reply.server));
  answer.match = std::string(textOf(reply.match));
  const auto action = enumOf<JoinAction>(reply.action, pool_JOIN_ENTER + 1);
  const auto outcome = enumOf<JoinOutcome>(reply.outcome, pool_JOIN_STALE_SEQUENCE + 1);
  if (!action || !outcome) return fail<JoinAnswer>("join reply", "unknown action or outcome");
  answer.action = *action;
  answer.outcome = *outcome;
  answer.reason = std::string(textOf(reply.reason));
  answer.seat = seatNumber(reply.seat);
  answer.token = reply.seat_token;
  answer.last_seq = reply.last_seq;
  return Result<JoinAnswer>::ok(std::move(answer));
}

Result<MatchView> fromWire(const pool_MatchState& state) {
  MatchView view;
  view.match = std::string(textOf(state.match));
  const std::string what = "match state " + view.match;
  view.revision = state.revision;
  const auto phase = enumOf<MatchPhase>(state.phase, pool_PHASE_CLOSED + 1);
  const auto in_hand = enumOf<rules::BallInHand>(state.ball_in_hand, pool_IN_HAND_IN_THE_D + 1);
  const auto end = enumOf<rules::GameEnd>(state.end, pool_END_THREE_MISSES + 1);
  if (!phase || !in_hand || !end) return fail<MatchView>(what, "unknown enum value");
  view.phase = *phase;
  view.ball_in_hand = *in_hand;
  view.end = *end;
  for (std::size_t i = 0; i < 2; ++i) {
    const auto seat = seatOf(state.seats[i]);
    if (!seat) return fail<MatchView>(what, "unknown group");
    view.seats[i] = *seat;
    view.seats[i].last_seq = state.seat_seq[i];
    view.seats[i].extensions_left = state.extensions_left[i];
    view.seats[i].fouls_in_row = state.fouls_in_row[i];
  }
  auto settings = settingsOf(state.game, state.race_to, state.breaks, state.shot_clock_limit,
                             state.practice, state.points_to);
  if (!settings) return fail<MatchView>(what, settings.error());
  view.settings = *settings;
  view.shot_clock_total = state.shot_clock_total;
  view.standard_physics = state.standard_physics;
  std::copy(std::begin(state.coefficients), std::end(state.coefficients),
            view.coefficients.begin());
  view.undo_depth = state.undo_depth;
  for (std::size_t i = 0; i < 2; ++i) {
    view.seats[i].points = state.points[i];
    view.seats[i].innings = state.innings[i];
    view.seats[i].high_run = state.high_run[i];
  }
  view.run = state.run;
  if (state.cue_ball > physics::kMaxBallId) return fail<MatchView>(what, "cue_ball: not a ball id");
  view.cue_ball = state.cue_ball;
  if (state.ball_on > physics::kMaxBallId) return fail<MatchView>(what, "ball_on: not a ball id");
  view.ball_on = state.ball_on;
  view.free_ball = state.free_ball;
  for (std::size_t i = 0; i < 2; ++i) view.seats[i].misses = state.misses[i];
  view.shooter = seatNumber(state.shooter);
  view.breaker = seatNumber(state.breaker);
  view.rack = state.rack;
  view.shot_number = state.shot_number;
  auto options = choicesOf(state.options);
  if (!options) return fail<MatchView>(what, options.error());
  view.options = std::move(*options);
  view.shot_clock = state.shot_clock;
  view.winner = seatNumber(state.winner);
  view.last_verdict = std::string(textOf(state.last_verdict));
  auto balls = getBalls(state.balls);
  if (!balls) return fail<MatchView>(what, balls.error());
  view.balls = std::move(*balls);
  return Result<MatchView>::ok(std::move(view));
}

Result<ShotReport> fromWire(const pool_ShotResult& result) {
  ShotReport report;
  report.match = std::string(textOf(result.match));
  const std::string what = "shot result " + report.match;
  report.seat = seatNumber(result.seat);
  report.seq = result.seq;
  report.shot_number = result.shot_number;
  report.accepted = result.accepted;
  const auto reason = enumOf<RejectReason>(result.reject_reason, pool_REJECT_BAD_PRACTICE + 1);
  const auto in_hand = enumOf<rules::BallInHand>(result.ball_in_hand, pool_IN_HAND_IN_THE_D + 1);
  const auto end = enumOf<rules::GameEnd>(result.end, pool_END_THREE_MISSES + 1);
  if (!reason || !in_hand || !end) return fail<ShotReport>(what, "unknown enum value");
  report.reject_reason = *reason;
  report.ball_in_hand = *in_hand;
  report.end = *end;
  report.reject_text = std::string(textOf(result.reject_text));
  auto events = getEvents(result.events);
  auto fouls = foulsOf(result.fouls);
  auto options = choicesOf(result.options);
  if (!events) return fail<ShotReport>(what, events.error());
  if (!fouls) return fail<ShotReport>(what, fouls.error());
  if (!options) return fail<ShotReport>(what, options.error());
  report.events = std::move(*events);
  report.fouls = std::move(*fouls);
  report.options = std::move(*options);
  for (auto id : elementsOf(result.pocketed)) report.pocketed.push_back(id);
  report.turn_continues = result.turn_continues;
  report.next_shooter = seatNumber(result.next_shooter);
  report.game_over = result.game_over;
  report.winner = seatNumber(result.winner);
  report.verdict_text = std::string(textOf(result.verdict_text));
  report.scored = result.scored;
  return Result<ShotReport>::ok(std::move(report));
}

Result<TableFrame> fromWire(const pool_TableSnapshot& snapshot) {
  TableFrame frame;
  frame.match = std::string(textOf(snapshot.match));
  frame.frame = snapshot.frame;
  frame.sim_time = snapshot.sim_time;
  frame.shot_number = snapshot.shot_number;
  auto balls = getBalls(snapshot.balls);
  if (!balls) return fail<TableFrame>("snapshot " + frame.match, balls.error());
  frame.balls = std::move(*balls);
  return Result<TableFrame>::ok(std::move(frame));
}

Sample<pool_JoinRequest> toWire(const SeatRequest& fields) {
  Sample<pool_JoinRequest> sample;
  pool_JoinRequest& request = *sample;
  setText(request.client, fields.client);
  request.request = fields.request;
  request.protocol_version = fields.protocol_version;
  setText(request.match, fields.match);
  request.action = wireOf<pool_JoinAction>(fields.action);
  request.seat = static_cast<std::int16_t>(fields.seat);
  setText(request.name, fields.name);
  request.seat_token = fields.token;
  setBytes(request.public_key, fields.public_key, kPublicKeyBytes);
  request.seq = fields.seq;
  setBytes(request.signature, fields.signature, kSignatureBytes);
  request.has_settings = fields.settings.has_value();
  if (fields.settings) {
    request.game = static_cast<std::uint8_t>(rules::gameNumber(fields.settings->game));
    request.race_to = static_cast<std::uint16_t>(fields.settings->race_to);
    request.breaks = wireOf<pool_BreakOrder>(fields.settings->breaks);
    request.shot_clock = fields.settings->shot_clock;
    request.practice = fields.settings->practice;
    request.points = static_cast<std::uint16_t>(fields.settings->points);
  }
  if (fields.opening) {
    request.tournament_format = static_cast<std::uint8_t>(fields.opening->format);
    request.entrants = static_cast<std::uint8_t>(std::clamp(fields.opening->entrants, 0, 255));
    request.handicap = fields.opening->handicap;
  }
  return sample;
}

Result<SeatRequest> fromWire(const pool_JoinRequest& r) {
  const auto action = enumOf<JoinAction>(r.action, pool_JOIN_ENTER + 1);
  if (!action) return Result<SeatRequest>::fail("action: not a known join action");
  if (!terminated(r.client) || !terminated(r.match) || !terminated(r.name)) {
    return Result<SeatRequest>::fail("client, match, name: text must fit its bound");
  }
  SeatRequest c;
  c.client = std::string(textOf(r.client));
  c.request = r.request;
  c.protocol_version = r.protocol_version;
  c.match = std::string(textOf(r.match));
  c.action = *action;
  c.seat = r.seat;
  c.name = std::string(textOf(r.name));
  c.token = r.seat_token;
  const auto key = elementsOf(r.public_key);
  c.public_key.assign(key.begin(), key.end());
  c.seq = r.seq;
  const auto signature = elementsOf(r.signature);
  c.signature.assign(signature.begin(), signature.end());
  if (r.has_settings) {
    auto settings = settingsOf(r.game, r.race_to, r.breaks, r.shot_clock, r.practice, r.points);
    if (!settings) return Result<SeatRequest>::fail("settings: " + settings.error());
    c.settings = *settings;
  }
  // An entry into "new" opens a tournament: its format, entrants and handicap cross with it.
  if (c.action == JoinAction::Enter && c.match == kNewMatch) {
    if (r.tournament_format > static_cast<int>(TournamentFormat::RoundRobin)) {
      return Result<SeatRequest>::fail("tournament_format: not a known format");
    }
    c.opening = TournamentOpening{static_cast<TournamentFormat>(r.tournament_format), r.entrants,
                                  r.handicap};
  }
  return Result<SeatRequest>::ok(std::move(c));
}

Sample<pool_MatchInfo> toWire(const LobbyEntry& entry) {
  Sample<pool_MatchInfo> sample;
  pool_MatchInfo& info = *sample;
  setText(info.match, entry.match);
  setText(info.server, entry.server);
  setText(info.name, entry.name);
  setText(info.table, entry.table);
  info.phase = wireOf<pool_MatchPhase>(entry.phase);
  for (std::size_t s = 0; s < 2; ++s) setText(info.players[s], entry.players[s]);
  info.seats_taken = static_cast<std::uint8_t>(entry.seats_taken);
  info.spectators = entry.spectators;
  info.protocol_version = entry.protocol_version;
  info.game = static_cast<std::uint8_t>(rules::gameNumber(entry.settings.game));
  info.race_to = static_cast<std::uint16_t>(entry.settings.race_to);
  info.breaks = wireOf<pool_BreakOrder>(entry.settings.breaks);
  info.shot_clock_limit = entry.settings.shot_clock;
  info.practice = entry.settings.practice;
  info.points = static_cast<std::uint16_t>(entry.settings.points);
  info.standard_physics = entry.standard_physics;
  for (std::size_t s = 0; s < 2; ++s) {
    info.racks_won[s] = static_cast<std::uint16_t>(entry.racks_won[s]);
    info.ratings[s] = static_cast<std::uint16_t>(std::clamp(entry.ratings[s], 0, 65535));
    info.rack_points[s] = static_cast<std::uint16_t>(std::clamp(entry.rack_points[s], 0, 65535));
  }
  info.rack = entry.rack;
  info.shot_number = entry.shot_number;
  return sample;
}

Sample<pool_JoinReply> toWire(const JoinAnswer& answer) {
  Sample<pool_JoinReply> sample;
  pool_JoinReply& reply = *sample;
  setText(reply.client, answer.client);
  reply.request = answer.request;
  setText(reply.server, answer.server);
  setText(reply.match, answer.match);
  reply.action = wireOf<pool_JoinAction>(answer.action);
  reply.outcome = wireOf<pool_JoinOutcome>(answer.outcome);
  setText(reply.reason, answer.reason);
  reply.seat = static_cast<std::int16_t>(answer.seat);
  reply.seat_token = answer.token;
  reply.last_seq = answer.last_seq;
  return sample;
}

Sample<pool_MatchState> toWire(const MatchView& view) {
  Sample<pool_MatchState> sample;
  pool_MatchState& st = *sample;
  setText(st.match, view.match);
  st.revision = view.revision;
  st.phase = wireOf<pool_MatchPhase>(view.phase);
  for (std::size_t i = 0; i < 2; ++i) {
    st.seats[i] = seatStateOf(view.seats[i]);
    st.seat_seq[i] = view.seats[i].last_seq;
    st.extensions_left[i] = static_cast<std::uint8_t>(view.seats[i].extensions_left);
    st.fouls_in_row[i] = static_cast<std::uint8_t>(view.seats[i].fouls_in_row);
  }
  st.game = static_cast<std::uint8_t>(rules::gameNumber(view.settings.game));
  st.race_to = static_cast<std::uint16_t>(view.settings.race_to);
  st.breaks = wireOf<pool_BreakOrder>(view.settings.breaks);
  st.shot_clock_limit = view.settings.shot_clock;
  st.shot_clock_total = view.shot_clock_total;
  st.shot_clock_warning = view.clockWarning();
  st.practice = view.settings.practice;
  st.standard_physics = view.standard_physics;
  std::copy(view.coefficients.begin(), view.coefficients.end(), st.coefficients);
  st.undo_depth = static_cast<std::uint16_t>(view.undo_depth);
  st.points_to = static_cast<std::uint16_t>(view.settings.points);
  for (std::size_t i = 0; i < 2; ++i) {
    st.points[i] = static_cast<std::uint16_t>(view.seats[i].points);
    st.innings[i] = static_cast<std::uint16_t>(view.seats[i].innings);
    st.high_run[i] = static_cast<std::uint16_t>(view.seats[i].high_run);
  }
  st.run = static_cast<std::uint16_t>(view.run);
  st.cue_ball = static_cast<std::uint8_t>(view.cue_ball);
  st.ball_on = static_cast<std::uint8_t>(view.ball_on);
  st.free_ball = view.free_ball;
  for (std::size_t i = 0; i < 2; ++i)
    st.misses[i] = static_cast<std::uint8_t>(view.seats[i].misses);
  st.shooter = static_cast<std::int16_t>(view.shooter);
  st.breaker = static_cast<std::int16_t>(view.breaker);
  st.rack = view.rack;
  st.shot_number = view.shot_number;
  st.ball_in_hand = wireOf<pool_BallInHandKind>(view.ball_in_hand);
  putAll(st.options, view.options, wireChoice);
  st.shot_clock = view.shot_clock;
  st.winner = static_cast<std::int16_t>(view.winner);
  st.end = wireOf<pool_GameEnd>(view.end);
  setText(st.last_verdict, view.last_verdict);
  putBalls(st.balls, view.balls);
  return sample;
}

Sample<pool_ShotResult> toWire(const ShotReport& report) {
  Sample<pool_ShotResult> sample;
  pool_ShotResult& r = *sample;
  setText(r.match, report.match);
  r.seat = static_cast<std::int16_t>(report.seat);
  r.seq = report.seq;
  r.shot_number = report.shot_number;
  r.accepted = report.accepted;
  r.reject_reason = wireOf<pool_RejectReason>(report.reject_reason);
  setText(r.reject_text, report.reject_text);
  putEvents(r.events, report.events);
  putAll(r.fouls, report.fouls, [](rules::Foul f) { return wireOf<pool_FoulCode>(f); });
  const auto pocketed = resizeSequence(r.pocketed, static_cast<std::uint32_t>(std::min<std::size_t>(
                                                       report.pocketed.size(), pool_MAX_BALLS)));
  for (std::size_t i = 0; i < pocketed.size(); ++i) {
    pocketed[i] = static_cast<std::uint8_t>(report.pocketed[i]);
  }
  r.turn_continues = report.turn_continues;
  r.next_shooter = static_cast<std::int16_t>(report.next_shooter);
  r.ball_in_hand = wireOf<pool_BallInHandKind>(report.ball_in_hand);
  putAll(r.options, report.options, wireChoice);
  r.game_over = report.game_over;
  r.winner = static_cast<std::int16_t>(report.winner);
  r.end = wireOf<pool_GameEnd>(report.end);
  setText(r.verdict_text, report.verdict_text);
  r.scored = static_cast<std::uint16_t>(report.scored);
  return sample;
}

Sample<pool_TableSnapshot> toWire(const TableFrame& frame) {
  Sample<pool_TableSnapshot> sample;
  setText(sample->match, frame.match);
  sample->frame = frame.frame;
  sample->sim_time = frame.sim_time;
  sample->shot_number = frame.shot_number;
  putBalls(sample->balls, frame.balls);
  return sample;
}

}  // namespace pool::net
