// Each admin verb against the registry and the store, answered as one JSON line.
#include "server/admin_desk.h"

#include <spdlog/spdlog.h>
#include <nlohmann/json.hpp>

#include "core/hex.h"
#include "core/text.h"
#include "protocol/protocol_enums.h"
#include "server/store/ban_list.h"
#include "server/store/online_backup.h"

namespace pool::server {

namespace {

using Json = nlohmann::json;

std::string line(const Json& doc) {
  return doc.dump(-1, ' ', false, Json::error_handler_t::replace);
}

std::string done(Json doc) {
  doc["ok"] = true;
  return line(doc);
}

}  // namespace

std::string adminError(const std::string& why) {
  return line(Json{{"ok", false}, {"error", why}});
}

AdminDesk::AdminDesk(MatchRegistry& registry, store::MatchStore& store,
                     const ServerCounters& counters, std::string db_path)
    : registry_(registry),
      store_(store),
      counters_(counters),
      db_path_(std::move(db_path)),
      started_(std::chrono::steady_clock::now()) {}

void AdminDesk::loadBans() {
  for (const auto& b : store::bans(store_.database())) registry_.ban(b.public_key, b.reason);
}

AdminDesk::Reply AdminDesk::answer(const std::string& request) {
  auto parsed = admin::parseRequest(request);
  if (!parsed) return {false, adminError(parsed.error())};
  std::string reply;
  switch (parsed->verb) {
    case admin::Verb::Status:
      reply = status();
      break;
    case admin::Verb::List:
      reply = list();
      break;
    case admin::Verb::Close:
      reply = close(*parsed);
      break;
    case admin::Verb::Ban:
      reply = ban(*parsed);
      break;
    case admin::Verb::Unban:
      reply = unban(*parsed);
      break;
    case admin::Verb::Bans:
      reply = bans();
      break;
    case admin::Verb::Backup:
      reply = backup(*parsed);
      break;
    case admin::Verb::TournamentCreate:
      reply = createTournament(*parsed);
      break;
    case admin::Verb::TournamentStart:
      reply = startTournament(*parsed);
      break;
    case admin::Verb::TournamentCancel:
      reply = cancelTournament(*parsed);
      break;
    case admin::Verb::Tournaments:
      reply = listTournaments();
      break;
  }
  const Json doc = Json::parse(reply, nullptr, false);
  return {doc.is_object() && doc.value("ok", false), reply};
}

std::string AdminDesk::createTournament(const admin::AdminRequest& r) {
  if (!tournaments_) return adminError("this server runs no tournaments");
  TournamentSetup setup;
  setup.name = r.name;
  setup.format = r.format == "double"        ? protocol::TournamentFormat::DoubleElimination
                 : r.format == "round-robin" ? protocol::TournamentFormat::RoundRobin
                                             : protocol::TournamentFormat::SingleElimination;
  const auto game = rules::gameOfNumber(r.game);
  if (!game) return adminError("game: 8, 9, 10, 3 or 22");
  setup.game = *game;
  setup.race_to = r.race;
  setup.capacity = r.entrants;
  setup.handicap = r.handicap;
  auto id = tournaments_->create(setup);
  if (!id) return adminError(id.error());
  return done({{"tournament", *id}});
}

std::string AdminDesk::startTournament(const admin::AdminRequest& r) {
  if (!tournaments_) return adminError("this server runs no tournaments");
  if (auto started = tournaments_->start(r.tournament); !started) {
    return adminError(started.error());
  }
  return done({{"tournament", r.tournament}, {"started", true}});
}

std::string AdminDesk::cancelTournament(const admin::AdminRequest& r) {
  if (!tournaments_) return adminError("this server runs no tournaments");
  auto in_play = tournaments_->cancel(r.tournament);
  if (!in_play) return adminError(in_play.error());
  return done({{"tournament", r.tournament}, {"cancelled", true}, {"matches_go_on", *in_play}});
}

std::string AdminDesk::listTournaments() const {
  Json list = Json::array();
  if (tournaments_) {
    for (const auto& t : tournaments_->views()) {
      Json entrants = Json::array();
      for (const auto& e : t.entrants) {
        entrants.push_back({{"name", e.name}, {"seed", e.seed}, {"place", e.place}});
      }
      int decided = 0;
      for (const auto& m : t.matches) decided += m.state == 3 ? 1 : 0;
      list.push_back({{"tournament", t.tournament},
                      {"name", t.name},
                      {"format", protocol::toString(t.format)},
                      {"game", rules::toString(t.game)},
                      {"race_to", t.race_to},
                      {"phase", protocol::toString(t.phase)},
                      {"capacity", t.capacity},
                      {"handicap", t.handicap},
                      {"opened_by", t.opened_by.empty() ? Json(nullptr) : Json(t.opened_by)},
                      {"entrants", entrants},
                      {"matches", t.matches.size()},
                      {"decided", decided},
                      {"champion", t.champion >= 0
                                       ? Json(t.entrants[static_cast<std::size_t>(t.champion)].name)
                                       : Json(nullptr)}});
    }
  }
  return done({{"tournaments", list}});
}

std::string AdminDesk::status() const {
  std::uint64_t matches = 0, in_play = 0, players = 0, connected = 0, spectators = 0;
  for (Match* m : registry_.matches()) {
    if (m->closed()) continue;
    ++matches;
    if (m->inPlay()) ++in_play;
    spectators += m->spectators();
    for (const Seat& s : m->seats()) {
      players += s.taken() ? 1 : 0;
      connected += s.connected() ? 1 : 0;
    }
  }
  const double uptime =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
  const auto& c = counters_;
  return done({{"health", "ok"},
               {"server_id", registry_.serverId()},
               {"db", db_path_},
               {"uptime_s", static_cast<std::uint64_t>(uptime)},
               {"matches", matches},
               {"matches_in_play", in_play},
               {"players", players},
               {"players_connected", connected},
               {"spectators", spectators},
               {"commands_accepted", c.commands_accepted},
               {"commands_refused", c.commands_refused},
               {"joins_accepted", c.joins_accepted},
               {"joins_refused", c.joins_refused},
               {"admin_requests", c.admin_requests},
               {"admin_refused", c.admin_refused},
               {"commits", c.commits},
               {"commit_ms_last", c.commit_ms_last},
               {"commit_ms_mean", c.commitMsMean()},
               {"commit_ms_max", c.commit_ms_max}});
}

std::string AdminDesk::list() {
  Json matches = Json::array();
  for (Match* m : registry_.matches()) {
    if (m->closed()) continue;
    Json seats = Json::array();
    for (std::size_t i = 0; i < m->seats().size(); ++i) {
      const Seat& s = m->seats()[i];
      if (!s.taken()) continue;
      seats.push_back({{"seat", i},
                       {"player", s.player},
                       {"connected", s.connected()},
                       {"key", hexOf(s.public_key)},
                       {"banned", registry_.banReason(s.public_key) != nullptr}});
    }
    matches.push_back({{"id", m->id()},
                       {"name", m->name()},
                       {"phase", protocol::toString(m->phase())},
                       {"shot", m->shotNumber()},
                       {"spectators", m->spectators()},
                       {"players", seats}});
  }
  return done({{"matches", matches}});
}

std::string AdminDesk::close(const admin::AdminRequest& r) {
  if (!registry_.closeMatch(r.match, "closed by the operator: " + r.reason)) {
    return adminError("no open match " + escapedForLog(r.match));
  }
  spdlog::info("admin: closed match {} ({})", r.match, escapedForLog(r.reason));
  return done({{"closed", r.match}});
}

std::string AdminDesk::ban(const admin::AdminRequest& r) {
  const bool added = store::addBan(store_.database(), r.key, r.reason);  // kept before it applies
  registry_.ban(r.key, r.reason);
  spdlog::info("admin: banned key {} ({})", hexOf(r.key), escapedForLog(r.reason));
  return done({{"banned", hexOf(r.key)}, {"already", !added}});
}

std::string AdminDesk::unban(const admin::AdminRequest& r) {
  const bool removed = store::removeBan(store_.database(), r.key);
  registry_.unban(r.key);
  if (!removed) return adminError("key " + hexOf(r.key) + " is not banned");
  spdlog::info("admin: lifted the ban of key {}", hexOf(r.key));
  return done({{"unbanned", hexOf(r.key)}});
}

std::string AdminDesk::bans() {
  Json out = Json::array();
  for (const auto& b : store::bans(store_.database())) {
    out.push_back({{"key", hexOf(b.public_key)}, {"reason", b.reason}, {"since", b.banned_at}});
  }
  return done({{"bans", out}});
}

std::string AdminDesk::backup(const admin::AdminRequest& r) {
  const auto start = std::chrono::steady_clock::now();
  auto copy = store::backupTo(store_.database(), r.path);
  if (!copy) return adminError(copy.error());
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("admin: backup to {} ({} bytes, {:.1f} ms)", escapedForLog(copy->path), copy->bytes,
               ms);
  return done({{"backup", copy->path}, {"pages", copy->pages}, {"bytes", copy->bytes}, {"ms", ms}});
}

}  // namespace pool::server
