// JSON text of the lobby, tables, states, results and frames for the web page.
#include "client/web/web_json.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "client/app/scoreboard.h"
#include "client/app/spoken.h"
#include "client/render/chalk_marks.h"
#include "client/render/diamonds.h"
#include "client/render/lamps.h"
#include "client/render/palette.h"
#include "client/spectate/json_lines.h"
#include "core/hex.h"
#include "protocol/match_settings.h"
#include "table/assets.h"
#include "table/snooker_spots.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::web {
namespace {

using nlohmann::json;

json rgb(const glm::vec3& c) {
  return json::array({c.r, c.g, c.b});
}

json vec2(const Eigen::Vector2d& v) {
  return json::array({v.x(), v.y()});
}

/// A snooker frame's facts the page shows as the window's HUD does (client/app/scoreboard.h):
/// the ball on in words, reds left, points remaining, each seat's snookers required; null for
/// other games.
json snookerJson(const client::MatchView& view) {
  if (view.settings.game != rules::Game::Snooker) return nullptr;
  const app::SnookerBoard board = app::snookerBoard(view);
  return {{"ball_on", app::ballOnWords(view.ball_on, view.free_ball)},
          {"free_ball", view.free_ball},
          {"reds_left", board.reds_left},
          {"points_remaining", board.points_remaining},
          {"snookers_required", board.snookers_required}};
}

/// One ball as a compact array: id, position (m), orientation (w, x, y, z), on the table (1/0).
void appendBall(std::string& out, const physics::Ball& b) {
  fmt::format_to(std::back_inserter(out),
                 "[{},{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{:.5f},{}]", b.id, b.pos.x(),
                 b.pos.y(), b.pos.z(), b.orient.w(), b.orient.x(), b.orient.y(), b.orient.z(),
                 physics::onTable(b.state) ? 1 : 0);
}

}  // namespace

std::string ballsArray(const std::vector<physics::Ball>& balls) {
  std::string out = "[";
  for (std::size_t i = 0; i < balls.size(); ++i) {
    if (i) out += ',';
    appendBall(out, balls[i]);
  }
  out += ']';
  return out;
}

std::string tournamentsJson(const std::vector<const protocol::TournamentView*>& tournaments) {
  json list = json::array();
  for (const auto* t : tournaments) {
    json entrants = json::array();
    for (const auto& e : t->entrants) {
      entrants.push_back({{"name", e.name},
                          {"rating", e.rating},
                          {"seed", e.seed},
                          {"place", e.place},
                          {"withdrawn", e.withdrawn}});
    }
    json matches = json::array();
    for (const auto& m : t->matches) {
      matches.push_back({{"round", m.round},
                         {"a", m.a},
                         {"b", m.b},
                         {"state", m.state},
                         {"winner", m.winner},
                         {"racks_a", m.racks_a},
                         {"racks_b", m.racks_b},
                         {"forfeit", m.forfeit},
                         {"match", m.match},
                         {"spot_a", m.spot_a},
                         {"spot_b", m.spot_b}});
    }
    list.push_back({{"tournament", t->tournament},
                    {"server", t->server},
                    {"name", t->name},
                    {"format", protocol::toString(t->format)},
                    {"game", rules::toString(t->game)},
                    {"race_to", t->race_to},
                    {"phase", protocol::toString(t->phase)},
                    {"capacity", t->capacity},
                    {"handicap", t->handicap},
                    {"opened_by", t->opened_by},
                    {"entrants", entrants},
                    {"matches", matches},
                    {"champion", t->champion}});
  }
  return json{{"type", "tournaments"}, {"tournaments", list}}.dump(-1, ' ', false,
                                                                   json::error_handler_t::replace);
}

bool validTableName(const std::string& name) {
  return table::isSpecName(name);
}

std::string lobbyEntryJson(const client::LobbyEntry& e) {
  return json{{"match", e.match},
              {"server", e.server},
              {"name", e.name},
              {"table", e.table},
              {"phase", toString(e.phase)},
              {"in_play", protocol::inPlay(e.phase)},
              {"players", json::array({e.players[0], e.players[1]})},
              {"ratings", json::array({e.ratings[0], e.ratings[1]})},
              {"game", rules::toString(e.settings.game)},
              {"practice", e.settings.practice},
              {"racks_won", json::array({e.racks_won[0], e.racks_won[1]})},
              {"rack", e.rack},
              {"shot_number", e.shot_number},
              {"rack_points", json::array({e.rack_points[0], e.rack_points[1]})},
              {"race_to", e.settings.race_to},
              {"settings", protocol::describe(e.settings)},
              {"spectators", e.spectators}}
      .dump(-1, ' ', false, json::error_handler_t::replace);  // wire text: never thrown on
}

std::string lobbyJson(const std::vector<const std::string*>& entries) {
  std::string out = R"({"type":"lobby","matches":[)";
  for (std::size_t i = 0; i < entries.size(); ++i) {
    if (i) out += ',';
    out += *entries[i];
  }
  out += "]}";
  return out;
}

std::string playersJson(const std::vector<const protocol::PlayerStats*>& players,
                        std::size_t limit) {
  json list = json::array();
  for (const protocol::PlayerStats* s : players) {
    if (list.size() >= limit) break;
    list.push_back({{"server", s->server},
                    {"player", hexOf(s->key)},
                    {"name", s->name},
                    {"game", rules::toString(s->game)},
                    {"rating", s->rating},
                    {"rating_deviation", s->rating_deviation},
                    {"matches", s->matches},
                    {"matches_won", s->matches_won},
                    {"racks", s->racks},
                    {"racks_won", s->racks_won},
                    {"strokes", s->strokes},
                    {"attempts", s->attempts},
                    {"pots", s->pots},
                    {"breaks", s->breaks},
                    {"break_pots", s->break_pots},
                    {"break_and_runs", s->break_and_runs},
                    {"fouls", s->fouls},
                    {"safeties", s->safeties},
                    {"high_run", s->high_run}});
  }
  // Names come from the wire: bytes that are not UTF-8 are replaced, never thrown on.
  return json{{"type", "players"}, {"players", std::move(list)}}.dump(
      -1, ' ', false, json::error_handler_t::replace);
}

namespace {

/// A snooker table's baulk line, D and spots as the window chalks them
/// (render::ChalkMarks); null for a table without them.
json snookerMarks(const table::TableSpec& spec) {
  const auto spots = table::snookerSpotsFor(spec);
  if (!spots) return nullptr;
  return {{"baulk_x", spots->baulk_x},
          {"d_radius", spots->d_radius},
          {"spots",
           {{"yellow", vec2(spots->yellow)},
            {"green", vec2(spots->green)},
            {"brown", vec2(spots->brown)},
            {"blue", vec2(spots->blue)},
            {"pink", vec2(spots->pink)},
            {"black", vec2(spots->black)}}},
          {"line_width", render::ChalkMarks::kLineWidth},
          {"spot_radius", render::ChalkMarks::kSpotRadius},
          {"strength", render::ChalkMarks::kStrength}};
}

}  // namespace

Result<std::string> tableJson(const std::string& table_name) {
  if (!validTableName(table_name))
    return Result<std::string>::fail("not a table name: '" + table_name + "'");
  auto spec = table::loadTableSpec(table_name);
  if (!spec) return Result<std::string>::fail(spec.error());
  const table::TableGeometry geometry = table::buildTableGeometry(*spec);
  json noses = json::array();
  for (const auto& n : geometry.noses) {
    noses.push_back(
        {{"name", n.name}, {"a", vec2(n.a)}, {"b", vec2(n.b)}, {"normal", vec2(n.normal)}});
  }
  json holes = json::array();
  for (const auto& h : geometry.holes) {
    holes.push_back({{"name", h.name}, {"centre", vec2(h.centre)}, {"radius", h.radius}});
  }
  json lamps = json::array();
  for (const auto& p : render::lampPositions(geometry))
    lamps.push_back(json::array({p.x, p.y, p.z}));
  json balls = json::array();
  const render::BallSet set = render::ballSetOf(*spec);
  for (int id = 0; id <= render::maxBallIdOf(set); ++id) {
    const render::BallLook look = render::ballLook(id, set);
    balls.push_back(
        {{"colour", rgb(look.colour)}, {"striped", look.striped}, {"number", look.number}});
  }
  // The project's meshes the page draws the table and the hall with (pool-web serves them, and
  // makes a dressing for a table that has none in assets/), and the looks of their parts.
  const bool mesh = table::findAsset("tables/" + spec->name + ".obj").has_value();
  json meshes{{"room", "assets/hall/room.obj"}, {"shade", "assets/hall/lamp-shade.obj"}};
  meshes["table"] = mesh ? json("assets/tables/" + spec->name + ".obj") : json();
  meshes["dressing"] = mesh ? json("assets/hall/" + spec->name + ".obj") : json();
  json looks = json::object();
  for (const char* part :
       {"rail_top",       "rail_edge",     "apron",      "leg",        "underside",
        "pocket_liner",   "pocket_rim",    "floor",      "ceiling",    "wainscot",
        "moulding",       "wallpaper",     "stool_seat", "chrome",     "rack_wood",
        "rack_cue_shaft", "rack_cue_butt", "board",      "brass",      "bead_light",
        "bead_dark",      "gilt",          "canvas_sky", "canvas_land"}) {
    looks[part] = rgb(render::hallPartLook(part).colour);
  }
  json diamonds = json::array();
  for (const auto& d : render::diamondPositions(
           render::railExtent(geometry, static_cast<float>(spec->cushion_width)))) {
    diamonds.push_back(json::array({d.x, d.y, d.z}));
  }
  const json out{
      {"type", "table"},
      {"name", spec->name},
      {"length", spec->length},
      {"width", spec->width},
      {"cushion_width", spec->cushion_width},
      {"rail_width", spec->rail_width},
      {"nose_height", geometry.nose_height},
      {"ball_radius", spec->params.ball_radius},
      {"noses", noses},
      {"holes", holes},
      {"snooker_marks", snookerMarks(*spec)},
      {"lamps",
       {{"positions", lamps},
        {"inner_deg", render::kSpotInnerDeg},
        {"outer_deg", render::kSpotOuterDeg},
        {"high",
         {{"inner_deg", render::kHighSpotInnerDeg}, {"outer_deg", render::kHighSpotOuterDeg}}},
        {"gain", render::kLampGain},
        {"shade", rgb(render::shadeColour())},
        {"shade_radius", render::kShadeRadius},
        {"bulb", rgb(render::bulbColour())}}},
      {"colours",
       {{"felt", rgb(render::partLook("slate").colour)},
        {"cushion", rgb(render::partLook("cushion_head").colour)},
        {"wood", rgb(render::woodColour())},
        {"pocket", rgb(render::partLook("pocket_head_left_corner").colour)},
        {"chalk", rgb(render::chalkColour())},
        {"balls", balls}}},
      {"meshes", meshes},
      {"looks", looks},
      {"diamonds", diamonds},
      {"diamond_size", {render::kDiamondHalfLong, render::kDiamondHalfShort}}};
  return Result<std::string>::ok(out.dump());
}

std::string stateJson(const client::MatchView& view) {
  return fmt::format(
      R"({{"type":"state","match":{},"state":{},"balls":{},"settings":{},"verdict_words":{},)"
      R"("snooker":{}}})",
      json(view.match).dump(), client::matchStateLine(view), ballsArray(view.balls),
      json(protocol::describe(view.settings)).dump(),
      json(app::spokenText(view.last_verdict)).dump(), snookerJson(view).dump());
}

std::string resultJson(const client::ShotReport& report) {
  return fmt::format(R"({{"type":"result","match":{},"result":{},"verdict_words":{}}})",
                     json(report.match).dump(), client::shotResultLine(report),
                     json(app::spokenText(report.verdict_text)).dump());
}

std::string frameJson(const client::TableFrame& frame) {
  return fmt::format(R"({{"type":"frame","match":{},"shot":{},"frame":{},"t":{:.5f},"balls":{}}})",
                     json(frame.match).dump(), frame.shot_number, frame.frame, frame.sim_time,
                     ballsArray(frame.balls));
}

}  // namespace pool::web
