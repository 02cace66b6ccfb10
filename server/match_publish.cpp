// The match logic's state and answers as the protocol's published messages.
#include "server/match_publish.h"

#include <algorithm>

#include "protocol/protocol_version.h"
#include "rules/ball_groups.h"

namespace pool::server {

namespace {

int ballsLeft(const Match& match, rules::Group group) {
  const auto& balls = match.balls();
  if (match.settings().game == rules::Game::ThreeCushion) return 0;  // nothing to pot
  // 9- and 10-ball: both players shoot at every object ball on the table.
  if (match.settings().game != rules::Game::EightBall) {
    return static_cast<int>(std::count_if(balls.begin(), balls.end(), [](const auto& b) {
      return physics::onTable(b.state) && rules::isObjectBall(b.id);
    }));
  }
  // While the table is open each player has seven to go.
  if (group == rules::Group::None) return 7;
  return static_cast<int>(std::count_if(balls.begin(), balls.end(), [&](const auto& b) {
    return physics::onTable(b.state) && rules::groupOf(b.id) == group;
  }));
}

protocol::SeatView seatViewOf(const Match& match, int seat) {
  const Seat& s = match.seats()[static_cast<std::size_t>(seat)];
  const rules::Group group = match.game().groups[static_cast<std::size_t>(seat)];
  protocol::SeatView out;
  out.name = s.player;
  out.connected = s.connected();
  out.group = group;
  out.balls_left = ballsLeft(match, group);
  out.fouls = s.fouls;
  out.racks_won = s.racks_won;
  out.last_seq = s.last_seq;
  out.fouls_in_row = match.game().fouls_in_row[static_cast<std::size_t>(seat)];
  out.extensions_left = match.extensionsLeft(seat);
  const auto i = static_cast<std::size_t>(seat);
  out.points = match.game().points[i];
  out.innings = match.game().innings[i];
  out.high_run = match.game().high_run[i];
  out.misses = match.game().misses[i];
  return out;
}

}  // namespace

protocol::LobbyEntry lobbyEntryOf(const Match& match, const std::string& server_id) {
  protocol::LobbyEntry info;
  info.match = match.id();
  info.server = server_id;
  info.name = match.name();
  info.table = match.table().spec.name;
  info.phase = match.phase();
  for (std::size_t s = 0; s < 2; ++s) {
    const Seat& seat = match.seats()[s];
    info.players[s] = seat.player;
    info.seats_taken += seat.taken() ? 1 : 0;
  }
  info.spectators = static_cast<std::uint32_t>(match.spectators());
  info.protocol_version = protocol::kProtocolVersion;
  info.settings = match.settings();
  info.racks_won = {match.seats()[0].racks_won, match.seats()[1].racks_won};
  info.rack = match.phase() == MatchPhase::Lobby ? 0 : match.rack();
  info.shot_number = match.shotNumber();
  info.rack_points = {match.game().points[0], match.game().points[1]};
  info.standard_physics = match.standardPhysics();
  return info;
}

protocol::MatchView matchViewOf(const Match& match, std::optional<double> now) {
  const rules::GameState& game = match.game();
  const bool started = match.phase() != MatchPhase::Lobby;
  protocol::MatchView st;
  st.match = match.id();
  st.revision = static_cast<std::uint32_t>(match.revision());
  st.phase = match.phase();
  st.seats = {seatViewOf(match, 0), seatViewOf(match, 1)};
  st.shooter = match.inPlay() ? game.shooter : -1;
  st.breaker = started ? game.breaker : -1;
  st.rack = match.rack();
  st.shot_number = match.shotNumber();
  st.ball_in_hand = match.inPlay() ? game.ball_in_hand : rules::BallInHand::None;
  st.options = game.options;
  const auto left = now ? match.clockLeft(*now) : std::nullopt;
  st.shot_clock = left.value_or(-1.0);
  st.shot_clock_total = match.clockTotal();
  st.settings = match.settings();
  st.standard_physics = match.standardPhysics();
  st.coefficients = protocol::coefficientsOf(match.table().spec.params);
  st.undo_depth = static_cast<int>(match.undoDepth());
  st.winner = game.winner;
  st.end = game.end;
  st.last_verdict = match.lastVerdict();
  st.balls = match.balls();
  st.run = game.run;
  st.cue_ball = match.cueBallFor(game);
  st.ball_on = game.ball_on;
  st.free_ball = game.free_ball;
  return st;
}

protocol::ShotReport commandReport(const std::string& match, const CommandAnswer& answer) {
  protocol::ShotReport r;
  r.match = match;
  r.seat = answer.seat;
  r.seq = answer.seq;
  r.shot_number = answer.shot_number;
  r.accepted = answer.accepted();
  r.reject_reason = answer.rejection.reason;
  r.reject_text = answer.rejection.text;
  r.next_shooter = -1;
  r.winner = -1;
  return r;
}

protocol::ShotReport finalReport(const std::string& match, const ShotReport& report) {
  const rules::Verdict& v = report.verdict;
  protocol::ShotReport r;
  r.match = match;
  r.seat = report.seat;
  r.seq = report.seq;
  r.shot_number = report.shot_number;
  r.accepted = true;
  r.events = report.events;
  r.fouls = v.fouls;
  r.pocketed.assign(v.pocketed.begin(), v.pocketed.end());
  r.turn_continues = v.turn_continues;
  r.next_shooter = v.next_shooter;
  r.ball_in_hand = v.ball_in_hand;
  r.options = v.options;
  r.game_over = v.game_over;
  r.winner = v.winner;
  r.end = v.end;
  r.verdict_text = report.text.empty() ? rules::describe(v) : report.text;
  r.scored = v.scored;
  return r;
}

protocol::TableFrame frameOf(const std::string& match, std::uint32_t frame,
                             std::uint32_t shot_number, const physics::Sample& at) {
  return {match, frame, at.t, shot_number, at.balls};
}

protocol::JoinAnswer replyTo(const JoinCommand& command, const JoinAnswer& answer,
                             const std::string& server_id) {
  protocol::JoinAnswer reply;
  reply.client = command.client;
  reply.request = command.request;
  reply.server = server_id;
  reply.match = answer.match.empty() ? command.match : answer.match;
  reply.action = command.action;
  reply.outcome = answer.outcome;
  reply.reason = answer.reason;
  reply.seat = answer.seat;
  reply.token = answer.token;
  reply.last_seq = answer.last_seq;
  return reply;
}

protocol::CommandLimits commandLimits(const table::TableSpec& spec) {
  protocol::CommandLimits limits;
  limits.miscue_limit = spec.params.miscue_limit;
  limits.half_length = spec.length / 2;
  limits.half_width = spec.width / 2;
  return limits;
}

protocol::CommandLimits serverLimits(const table::TableSpec& pool_table) {
  protocol::CommandLimits limits = commandLimits(pool_table);
  for (const rules::GameInfo& game : rules::allGames()) {
    if (!game.table) continue;  // played on the pool table
    const auto spec = table::loadTableSpec(game.table);
    if (!spec) continue;
    limits.half_length = std::max(limits.half_length, spec->length / 2);
    limits.half_width = std::max(limits.half_width, spec->width / 2);
  }
  return limits;
}

}  // namespace pool::server
