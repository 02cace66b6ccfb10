// JSON lines of what a spectator sees.
#include "client/spectate/json_lines.h"

#include <nlohmann/json.hpp>

namespace pool::client {
namespace {

using nlohmann::json;

json seatJson(const SeatView& seat) {
  return {{"name", seat.name},
          {"connected", seat.connected},
          {"group", rules::toString(seat.group)},
          {"balls_left", seat.balls_left},
          {"fouls", seat.fouls},
          {"racks_won", seat.racks_won},
          {"points", seat.points},
          {"innings", seat.innings},
          {"high_run", seat.high_run},
          {"misses", seat.misses}};
}

json choicesJson(const std::vector<rules::Choice>& choices) {
  json out = json::array();
  for (auto c : choices) out.push_back(rules::toString(c));
  return out;
}

int ballsOnTable(const std::vector<physics::Ball>& balls) {
  int n = 0;
  for (const auto& b : balls) n += physics::onTable(b.state) ? 1 : 0;
  return n;
}

}  // namespace

std::string spectatingLine(const JoinAnswer& answer) {
  return json{{"type", "spectating"}, {"match", answer.match}, {"server", answer.server}}.dump();
}

std::string matchStateLine(const MatchView& view) {
  json seats = json::array({seatJson(view.seats[0]), seatJson(view.seats[1])});
  json on_table = json::array();
  for (const auto& b : view.balls) {
    if (physics::onTable(b.state)) on_table.push_back(b.id);
  }
  return json{{"type", "match_state"},
              {"match", view.match},
              {"revision", view.revision},
              {"phase", toString(view.phase)},
              {"rack", view.rack},
              {"shot_number", view.shot_number},
              {"shooter", view.shooter},
              {"breaker", view.breaker},
              {"ball_in_hand", rules::toString(view.ball_in_hand)},
              {"options", choicesJson(view.options)},
              {"winner", view.winner},
              {"end", rules::toString(view.end)},
              {"seats", seats},
              {"balls", view.balls.size()},
              {"balls_on_table", ballsOnTable(view.balls)},
              {"on_table", on_table},
              {"game", rules::toString(view.settings.game)},
              {"points_to", view.settings.points},
              {"race_to", view.settings.race_to},
              {"run", view.run},
              {"cue_ball", view.cue_ball},
              {"ball_on", view.ball_on},
              {"free_ball", view.free_ball},
              {"last_verdict", view.last_verdict}}
      .dump();
}

std::string shotResultLine(const ShotReport& report) {
  json fouls = json::array();
  for (auto f : report.fouls) fouls.push_back(rules::toString(f));
  return json{{"type", "shot_result"},
              {"match", report.match},
              {"seat", report.seat},
              {"seq", report.seq},
              {"shot_number", report.shot_number},
              {"accepted", report.accepted},
              {"final", report.final()},
              {"reject_reason", toString(report.reject_reason)},
              {"reject_text", report.reject_text},
              {"events", report.events.size()},
              {"fouls", fouls},
              {"pocketed", report.pocketed},
              {"turn_continues", report.turn_continues},
              {"next_shooter", report.next_shooter},
              {"ball_in_hand", rules::toString(report.ball_in_hand)},
              {"options", choicesJson(report.options)},
              {"game_over", report.game_over},
              {"winner", report.winner},
              {"end", rules::toString(report.end)},
              {"verdict", report.verdict_text}}
      .dump();
}

std::string snapshotsLine(const std::string& match, std::uint32_t shot_number, std::uint32_t count,
                          std::uint32_t first_frame, std::uint32_t last_frame) {
  return json{{"type", "snapshots"},        {"match", match},
              {"shot_number", shot_number}, {"count", count},
              {"first_frame", first_frame}, {"last_frame", last_frame}}
      .dump();
}

}  // namespace pool::client
