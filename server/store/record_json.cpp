// Field-by-field JSON with nlohmann-json; enums as their numbers, vectors as arrays.
#include "server/store/record_json.h"

#include <nlohmann/json.hpp>

#include "scenario/cue_shot_json.h"
#include "server/store/sqlite_db.h"

namespace pool::store {

namespace {

using Json = nlohmann::json;

Json vec(const Eigen::Vector3d& v) {
  return Json::array({v.x(), v.y(), v.z()});
}

Eigen::Vector3d vec3(const Json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>(), j.at(2).get<double>()};
}

Json vec(const Eigen::Vector2d& v) {
  return Json::array({v.x(), v.y()});
}

Eigen::Vector2d vec2(const Json& j) {
  return {j.at(0).get<double>(), j.at(1).get<double>()};
}

template <class E>
int num(E e) {
  return static_cast<int>(e);
}

template <class E>
E enumAt(const Json& j, const char* key) {
  return static_cast<E>(j.at(key).get<int>());
}

template <class E>
Json enums(const std::vector<E>& list) {
  Json out = Json::array();
  for (E e : list) out.push_back(num(e));
  return out;
}

template <class E>
std::vector<E> enumsFrom(const Json& j) {
  std::vector<E> out;
  for (const auto& e : j) out.push_back(static_cast<E>(e.get<int>()));
  return out;
}

/// Parses `text` and reads it with `read`, turning any failure into one StoreError line.
template <class F>
auto parse(const std::string& text, const char* what, F read) {
  try {
    return read(Json::parse(text));
  } catch (const Json::exception& e) {
    throw StoreError(std::string("stored ") + what + " unreadable: " + e.what());
  }
}

Json ballOf(const physics::Ball& b) {
  const auto& q = b.orient;
  return {
      {"id", b.id},        {"pos", vec(b.pos)},   {"q", Json::array({q.w(), q.x(), q.y(), q.z()})},
      {"vel", vec(b.vel)}, {"w", vec(b.ang_vel)}, {"state", num(b.state)},
      {"pocket", b.pocket}};
}

physics::Ball ballAt(const Json& j) {
  physics::Ball b;
  b.id = j.at("id").get<int>();
  b.pos = vec3(j.at("pos"));
  const Json& q = j.at("q");
  b.orient = physics::Quat(q.at(0).get<double>(), q.at(1).get<double>(), q.at(2).get<double>(),
                           q.at(3).get<double>());
  b.vel = vec3(j.at("vel"));
  b.ang_vel = vec3(j.at("w"));
  b.state = enumAt<physics::MotionState>(j, "state");
  b.pocket = j.at("pocket").get<std::string>();
  return b;
}

Json pair(const std::array<int, 2>& a) {
  return Json::array({a[0], a[1]});
}

std::array<int, 2> pairAt(const Json& j, const char* key) {
  return {j.at(key).at(0).get<int>(), j.at(key).at(1).get<int>()};
}

Json gameOf(const rules::GameState& s) {
  Json out = {{"phase", num(s.phase)},
              {"shooter", s.shooter},
              {"breaker", s.breaker},
              {"groups", Json::array({num(s.groups[0]), num(s.groups[1])})},
              {"ball_in_hand", num(s.ball_in_hand)},
              {"options", enums(s.options)},
              {"dry_turns", s.dry_turns},
              {"winner", s.winner},
              {"end", num(s.end)},
              {"fouls_in_row", Json::array({s.fouls_in_row[0], s.fouls_in_row[1]})},
              {"push_out", s.push_out}};
  // Three-cushion's score, written where a game has one (a pool rack's record is as before).
  const bool scored =
      s.points != std::array<int, 2>{0, 0} || s.innings != std::array<int, 2>{0, 0} || s.run != 0;
  if (scored) {
    out["points"] = pair(s.points);
    out["innings"] = pair(s.innings);
    out["high_run"] = pair(s.high_run);
    out["run"] = s.run;
  }
  // Snooker's ball on, free ball, misses and the position a miss can put back, where a frame has
  // them (a red on and nothing else pending writes nothing: the default).
  if (s.ball_on != 0 || s.free_ball || s.misses != std::array<int, 2>{0, 0} ||
      !s.before_miss.empty() || s.before_miss_in_hand != rules::BallInHand::None ||
      s.before_miss_on != 0 || s.before_miss_free_ball) {
    Json layout = Json::array();
    for (const auto& b : s.before_miss) layout.push_back({b.id, b.x, b.y});
    out["snooker"] = {{"ball_on", s.ball_on},
                      {"free_ball", s.free_ball},
                      {"misses", pair(s.misses)},
                      {"before_miss", layout},
                      {"before_miss_in_hand", num(s.before_miss_in_hand)},
                      {"before_miss_on", s.before_miss_on},
                      {"before_miss_free_ball", s.before_miss_free_ball}};
  }
  return out;
}

rules::GameState gameAt(const Json& j) {
  rules::GameState s;
  s.phase = enumAt<rules::Phase>(j, "phase");
  s.shooter = j.at("shooter").get<int>();
  s.breaker = j.at("breaker").get<int>();
  for (std::size_t i = 0; i < 2; ++i) {
    s.groups[i] = static_cast<rules::Group>(j.at("groups").at(i).get<int>());
  }
  s.ball_in_hand = enumAt<rules::BallInHand>(j, "ball_in_hand");
  s.options = enumsFrom<rules::Choice>(j.at("options"));
  s.dry_turns = j.at("dry_turns").get<int>();
  s.winner = j.at("winner").get<int>();
  s.end = enumAt<rules::GameEnd>(j, "end");
  // Written since 9- and 10-ball (older records: none).
  if (j.contains("fouls_in_row")) {
    for (std::size_t i = 0; i < 2; ++i) s.fouls_in_row[i] = j.at("fouls_in_row").at(i).get<int>();
  }
  if (j.contains("push_out")) s.push_out = j.at("push_out").get<bool>();
  if (j.contains("points")) {
    s.points = pairAt(j, "points");
    s.innings = pairAt(j, "innings");
    s.high_run = pairAt(j, "high_run");
    s.run = j.at("run").get<int>();
  }
  if (j.contains("snooker")) {
    const Json& k = j.at("snooker");
    s.ball_on = k.at("ball_on").get<int>();
    s.free_ball = k.at("free_ball").get<bool>();
    s.misses = pairAt(k, "misses");
    for (const auto& b : k.at("before_miss")) {
      s.before_miss.push_back({b.at(0).get<int>(), b.at(1).get<double>(), b.at(2).get<double>()});
    }
    s.before_miss_in_hand = enumAt<rules::BallInHand>(k, "before_miss_in_hand");
    s.before_miss_on = k.at("before_miss_on").get<int>();
    s.before_miss_free_ball = k.value("before_miss_free_ball", false);
  }
  return s;
}

}  // namespace

std::string ballsJson(const std::vector<physics::Ball>& balls) {
  Json out = Json::array();
  for (const auto& b : balls) out.push_back(ballOf(b));
  return out.dump();
}

std::vector<physics::Ball> ballsFrom(const std::string& text) {
  return parse(text, "balls", [](const Json& j) {
    std::vector<physics::Ball> out;
    for (const auto& b : j) out.push_back(ballAt(b));
    return out;
  });
}

std::string settingsJson(const protocol::MatchSettings& s) {
  Json out{{"game", rules::gameNumber(s.game)},
           {"race_to", s.race_to},
           {"breaks", num(s.breaks)},
           {"shot_clock", s.shot_clock}};
  if (s.game == rules::Game::ThreeCushion) out["points"] = s.points;
  return out.dump();
}

protocol::MatchSettings settingsFrom(const std::string& text) {
  return parse(text, "settings", [](const Json& j) {
    protocol::MatchSettings s;
    if (j.contains("game")) {
      const auto game = rules::gameOfNumber(j.at("game").get<int>());
      if (!game) throw StoreError("stored settings unreadable: not a game");
      s.game = *game;
    }
    if (j.contains("race_to")) s.race_to = j.at("race_to").get<int>();
    if (j.contains("breaks")) s.breaks = enumAt<protocol::BreakOrder>(j, "breaks");
    if (j.contains("shot_clock")) s.shot_clock = j.at("shot_clock").get<double>();
    if (j.contains("points")) s.points = j.at("points").get<int>();
    return s;
  });
}

std::string gameJson(const rules::GameState& state) {
  return gameOf(state).dump();
}

rules::GameState gameFrom(const std::string& text) {
  return parse(text, "rules state", gameAt);
}

std::string verdictJson(const rules::Verdict& v) {
  Json respots = Json::array();
  for (const auto& r : v.respots) respots.push_back({{"id", r.id}, {"pos", vec(r.pos)}});
  const Json out = {{"fouls", enums(v.fouls)},
                    {"pocketed", v.pocketed},
                    {"off_table", v.off_table},
                    {"turn_continues", v.turn_continues},
                    {"assigned", num(v.assigned)},
                    {"next_shooter", v.next_shooter},
                    {"ball_in_hand", num(v.ball_in_hand)},
                    {"respots", respots},
                    {"options", enums(v.options)},
                    {"rerack", v.rerack},
                    {"stalemate", v.stalemate},
                    {"game_over", v.game_over},
                    {"winner", v.winner},
                    {"end", num(v.end)},
                    {"next", gameOf(v.next)}};
  // A score, a snooker penalty and a miss, written where a verdict has them (a pool shot's record
  // is as before).
  if (v.scored == 0 && v.penalty == 0 && !v.miss) return out.dump();
  Json with_score = out;
  if (v.scored != 0) with_score["scored"] = v.scored;
  if (v.penalty != 0) with_score["penalty"] = v.penalty;
  if (v.miss) with_score["miss"] = true;
  return with_score.dump();
}

rules::Verdict verdictFrom(const std::string& text) {
  return parse(text, "verdict", [](const Json& j) {
    rules::Verdict v;
    v.fouls = enumsFrom<rules::Foul>(j.at("fouls"));
    v.pocketed = j.at("pocketed").get<std::vector<int>>();
    v.off_table = j.at("off_table").get<std::vector<int>>();
    v.turn_continues = j.at("turn_continues").get<bool>();
    v.assigned = enumAt<rules::Group>(j, "assigned");
    v.next_shooter = j.at("next_shooter").get<int>();
    v.ball_in_hand = enumAt<rules::BallInHand>(j, "ball_in_hand");
    for (const auto& r : j.at("respots")) {
      v.respots.push_back({r.at("id").get<int>(), vec2(r.at("pos"))});
    }
    v.options = enumsFrom<rules::Choice>(j.at("options"));
    v.rerack = j.at("rerack").get<bool>();
    v.stalemate = j.at("stalemate").get<bool>();
    v.game_over = j.at("game_over").get<bool>();
    v.winner = j.at("winner").get<int>();
    v.end = enumAt<rules::GameEnd>(j, "end");
    v.next = gameAt(j.at("next"));
    if (j.contains("scored")) v.scored = j.at("scored").get<int>();
    if (j.contains("penalty")) v.penalty = j.at("penalty").get<int>();
    if (j.contains("miss")) v.miss = j.at("miss").get<bool>();
    return v;
  });
}

std::string eventsJson(const physics::EventLog& events) {
  Json out = Json::array();
  for (const auto& e : events) {
    out.push_back({{"t", e.t},
                   {"type", num(e.type)},
                   {"a", e.ball_a},
                   {"b", e.ball_b},
                   {"where", e.where},
                   {"speed", e.speed},
                   {"pos", vec(e.pos)}});
  }
  return out.dump();
}

physics::EventLog eventsFrom(const std::string& text) {
  return parse(text, "events", [](const Json& j) {
    physics::EventLog out;
    for (const auto& e : j) {
      physics::Event ev;
      ev.t = e.at("t").get<double>();
      ev.type = enumAt<physics::EventType>(e, "type");
      ev.ball_a = e.at("a").get<int>();
      ev.ball_b = e.at("b").get<int>();
      ev.where = e.at("where").get<std::string>();
      ev.speed = e.at("speed").get<double>();
      ev.pos = vec3(e.at("pos"));
      out.push_back(ev);
    }
    return out;
  });
}

std::string intentJson(const rules::Intent& intent) {
  Json out = {{"pocket", intent.pocket}, {"safety", intent.safety}};
  if (intent.ball) out["ball"] = *intent.ball;
  if (intent.choice) out["choice"] = num(*intent.choice);
  return out.dump();
}

rules::Intent intentFrom(const std::string& text) {
  return parse(text, "intent", [](const Json& j) {
    rules::Intent intent;
    intent.pocket = j.at("pocket").get<std::string>();
    intent.safety = j.at("safety").get<bool>();
    if (j.contains("ball")) intent.ball = j.at("ball").get<int>();
    if (j.contains("choice")) intent.choice = enumAt<rules::Choice>(j, "choice");
    return intent;
  });
}

std::string commandJson(const protocol::ShotRequest& c) {
  Json out = {{"match", c.match},
              {"seat", c.seat},
              {"token", c.seat_token},
              {"seq", c.seq},
              {"called_pocket", c.called_pocket},
              {"safety", c.safety},
              {"option", num(c.option)},
              {"signature", c.signature}};
  out.update(scenario::cueShotJson(c.cue));
  if (c.called_ball) out["called_ball"] = *c.called_ball;
  if (c.cue_ball_at) out["cue_ball_at"] = vec(*c.cue_ball_at);
  return out.dump();
}

protocol::ShotRequest commandFrom(const std::string& text) {
  return parse(text, "command", [](const Json& j) {
    protocol::ShotRequest c;
    c.match = j.at("match").get<std::string>();
    c.seat = j.at("seat").get<int>();
    c.seat_token = j.at("token").get<std::uint64_t>();
    c.seq = j.at("seq").get<std::uint32_t>();
    c.cue.yaw = j.at("yaw").get<double>();
    c.cue.tip_side = j.at("tip_side").get<double>();
    c.cue.tip_height = j.at("tip_height").get<double>();
    c.cue.elevation = j.at("elevation").get<double>();
    c.cue.speed = j.at("speed").get<double>();
    c.cue.speed_is_ball = j.at("speed_is_ball").get<bool>();
    c.called_pocket = j.at("called_pocket").get<std::string>();
    c.safety = j.at("safety").get<bool>();
    c.option = enumAt<protocol::ShotOption>(j, "option");
    c.signature = j.at("signature").get<std::vector<std::uint8_t>>();
    if (j.contains("called_ball")) c.called_ball = j.at("called_ball").get<int>();
    if (j.contains("cue_ball_at")) c.cue_ball_at = vec2(j.at("cue_ball_at"));
    return c;
  });
}

}  // namespace pool::store
