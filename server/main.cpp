// pool-server: the authoritative 8-, 9- and 10-ball match server; wires the match logic to Cyclone
// DDS.
#include <signal.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <atomic>
#include <chrono>
#include <cstdlib>
#include <string>

#include "game/loaded_table.h"
#include "net/dds_error.h"
#include "net/server_id_probe.h"
#include "net/server_transport.h"
#include "protocol/protocol_version.h"
#include "protocol/server_signature.h"
#include "rules/game_rules.h"
#include "server/admin/admin_cli.h"
#include "server/admin/admin_listener.h"
#include "server/admin_desk.h"
#include "server/match/match_registry.h"
#include "server/match/match_replay.h"
#include "server/match/token_source.h"
#include "server/server_config.h"
#include "server/server_loop.h"
#include "server/store/match_store.h"

namespace {

std::atomic<bool> g_stop{false};

/// The exit code of a server that refuses to run beside a live one with its id (the systemd unit
/// does not restart on it: RestartPreventExitStatus).
constexpr int kExitDuplicateServer = 3;
/// How long the lobby is read for another server with our id before serving.
constexpr std::chrono::milliseconds kPeerWait{1500};
/// How long a server that saw entries of its id signed with its own key challenges the domain,
/// once a second, for a live server with that key (a copy of its database) to answer. A live one
/// answers within a pass of its loop once discovery has matched the challenge's writer (well
/// under a second on a LAN): ten seconds leave room for a loaded machine.
constexpr double kChallengeWindow = 10.0;

/// The warning for lobby entries of `server_id` that are not ours: no reason to stop.
std::string strangeEntries(const std::string& server_id, const pool::net::ServerSighting& seen) {
  std::string why = "a lobby entry under --server-id " + server_id + " (match " + seen.match +
                    ", server key " + seen.key_fingerprint + ")";
  if (!seen.problem.empty()) why += " that does not verify (" + seen.problem + ")";
  return why +
         " is not this database's: anyone can write such an entry, so it proves no other server "
         "live; serving (clients pin one key per server id and drop the other's samples)";
}

extern "C" void onSignal(int) {
  g_stop.store(true);
}

void installSignalHandlers() {
  struct sigaction action {};
  action.sa_handler = onSignal;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void setUpLogging(const pool::server::ServerConfig& config) {
  auto logger = spdlog::stderr_color_mt(config.name);
  spdlog::set_default_logger(logger);
  spdlog::set_level(spdlog::level::from_str(config.log_level));
}

pool::server::RegistryOptions registryOptions(const pool::server::ServerConfig& config) {
  pool::server::RegistryOptions options;
  options.server_id = config.server_id;
  options.table = config.table;
  options.max_matches = static_cast<std::size_t>(config.max_matches);
  options.match.snapshot_hz = config.snapshot_hz;
  options.match.unpaced = config.fast;
  options.rack_seed = config.rack_seed;
  options.match.settings = *pool::server::matchSettingsOf(config);
  options.protocol_version = pool::protocol::kProtocolVersion;
  return options;
}

/// Adopts every resumable match of `store`; returns how many.
int resume(pool::server::MatchRegistry& registry, pool::store::MatchStore& store) {
  registry.continueAfter(store.opened());
  int resumed = 0;
  for (const auto& match : store.matches()) {
    if (!pool::store::resumable(match)) continue;
    // Seated players are away from the start: the grace period runs from the resume.
    if (!registry.adopt(match, 0.0)) continue;
    spdlog::info("resumed {} ({}) at shot {}: {}", match.id, match.name, match.shot_number,
                 pool::rules::describe(match.game));
    ++resumed;
  }
  return resumed;
}

/// Serves matches, resuming those of `store` and keeping every change in it, and the operator on
/// the admin socket. Returns the exit code.
int serve(const pool::server::ServerConfig& config,
          std::shared_ptr<const pool::game::LoadedTable> kit, pool::store::MatchStore& store,
          const std::string& db_path) {
  using namespace pool::server;
  const std::string socket_path =
      config.admin_socket.empty() ? pool::admin::socketPathFor(db_path) : config.admin_socket;
  auto listener = pool::admin::AdminListener::open(socket_path);
  if (!listener && !config.admin_socket.empty()) {
    spdlog::error("--admin-socket {}", listener.error());
    return 1;
  }
  // The default socket beside the database may not fit (a long path): the games go on without.
  if (!listener) spdlog::warn("no admin socket: {} (set --admin-socket)", listener.error());
  store.setTable(config.table);
  const pool::protocol::KeyPair key = store.serverKey();
  RegistryOptions options = registryOptions(config);
  // The file keeps the server's id, so match ids go on where they stopped.
  if (options.server_id.empty()) options.server_id = store.serverId();
  MatchRegistry registry(options, std::move(kit));
  // The default game's own table (three-cushion's) must load before anyone sits down at it.
  if (auto table = registry.options().match.tables->forGame(options.match.settings.game); !table) {
    spdlog::error("--game {}: {}", pool::rules::toString(options.match.settings.game),
                  table.error());
    return 1;
  }
  // Another server live under this id with our key (a copy of this database) must not serve
  // beside us. Entries prove nothing (anyone writes one, a genuine one can be replayed): only a
  // server that answers a fresh challenge signed with our key does.
  pool::net::ServerIdProbe probe(config.domain);
  const auto seen = probe.look(registry.serverId(), key, kPeerWait);
  if (seen.strange) spdlog::warn("{}", strangeEntries(registry.serverId(), seen));
  if (seen.ours) {
    spdlog::warn(
        "server {} with this database's key is still seen (a run that crashed, or a replayed "
        "entry?): serving, and stopping if a live server with this key answers within {:.0f} s",
        registry.serverId(), kChallengeWindow);
  }
  const int resumed = resume(registry, store);
  const int opened = registry.keepFreeTables(config.tables);
  pool::net::ServerTransport transport(config.domain, key);
  ServerLoop loop(config, registry, transport, &store);
  if (seen.ours) {
    const std::string own = transport.participantGuid();
    const std::string id = registry.serverId();
    loop.guard([&probe, &key, own, id, challenged = -1.0](double now) mutable -> std::string {
      if (challenged > kChallengeWindow) return {};
      if (probe.answered(id, key, own)) {
        return "another server with this database's key and server id is still live on the "
               "domain after " +
               std::to_string(static_cast<int>(now)) +
               " s: it answered a challenge (a copy of this database?): stopping";
      }
      if (now - challenged < 1.0) return {};
      if (now > kChallengeWindow) {
        spdlog::info("no other server with this database's key answered in {:.0f} s: serving on",
                     kChallengeWindow);
        challenged = now;  // past the window: done
        return {};
      }
      probe.challenge(id);
      challenged = now;
      return {};
    });
  }
  AdminDesk desk(registry, store, loop.counters(), db_path);
  desk.loadBans();
  desk.tournaments(&loop.tournaments());
  if (listener) loop.admin(listener->get(), &desk);
  spdlog::info(
      "server {} on domain {}: {} free tables opened, {} resumed, {} Hz{}, db {}, admin {}",
      registry.serverId(), config.domain, opened, resumed, config.snapshot_hz,
      config.fast ? ", unpaced" : "", db_path, listener ? socket_path : "none");
  spdlog::info("server key fingerprint {} (clients pin it for server id {})",
               pool::protocol::fingerprint(key.public_key), registry.serverId());
  loop.run(g_stop);
  if (!loop.fault().empty()) {
    // The matches are the other server's too: no disposal notices. Deleting the writers would
    // dispose every instance they wrote (autodispose), so the process ends without deleting
    // them; every stored change is already committed.
    spdlog::error("{}", loop.fault());
    spdlog::default_logger()->flush();
    std::_Exit(kExitDuplicateServer);
  }
  spdlog::info("shutting down");
  loop.disposeAll();
  return 0;
}

/// Plays stored match config.replay again as a new match (beside --tables empty ones); writes
/// nothing. Returns the exit code.
int replayMatch(const pool::server::ServerConfig& config, pool::store::MatchStore& store) {
  using namespace pool::server;
  const auto stored = store.match(config.replay);
  if (!stored) {
    spdlog::error("--replay {}: no such match in the database", config.replay);
    return 1;
  }
  // A pool match replays on the table it was played on; a game with a table of its own
  // (three-cushion) moves onto it when its players sit down, the free tables beside it staying
  // this server's pool tables.
  auto kit = pool::game::loadSharedTable(
      pool::rules::isPool(stored->settings.game) ? store.tableOf(config.replay) : config.table);
  if (!kit) {
    spdlog::error("--replay {}: {}", config.replay, kit.error());
    return 1;
  }
  std::vector<ShotRecord> commands;
  for (auto& shot : store.shots(config.replay)) commands.push_back(std::move(shot.record));
  const std::size_t count = commands.size();
  MatchRegistry registry(registryOptions(config), *kit);
  for (int i = 0; i < config.tables; ++i) registry.open();
  Match* target =
      registry.open("Replay of " + stored->id, stored->rack_seed, stored->rack_generator);
  TokenSource tokens(randomSeed());
  MatchReplay replay(*stored, std::move(commands), *target, {tokens.token(), tokens.token()},
                     config.fast ? 0.0 : 1.0);
  pool::net::ServerTransport transport(config.domain, store.serverKey());
  ServerLoop loop(config, registry, transport);
  loop.replay(&replay);
  spdlog::info("server {} on domain {}: replaying {} ({} commands) as {}", registry.serverId(),
               config.domain, stored->id, count, target->id());
  loop.run(g_stop);
  spdlog::info("shutting down");
  loop.disposeAll();
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace pool::server;
  if (pool::admin::isAdminCommand(argc, argv)) {
    return pool::admin::runAdminCommand(argc, argv, pool::store::defaultDbPath());
  }
  const ConfigOutcome parsed = parseConfig(argc, argv);
  if (parsed.exit_code) return *parsed.exit_code;
  const ServerConfig& config = parsed.config;
  setUpLogging(config);
  installSignalHandlers();

  auto kit = pool::game::loadSharedTable(config.table);
  if (!kit) {
    spdlog::error("{}", kit.error());
    return 1;
  }
  const std::string db_path = config.db.empty() ? pool::store::defaultDbPath() : config.db;
  auto store = pool::store::MatchStore::open(db_path);
  if (!store) {
    spdlog::error("--db {}", store.error());
    return 1;
  }
  try {
    if (!config.replay.empty()) return replayMatch(config, **store);
    return serve(config, *kit, **store, db_path);
  } catch (const pool::net::DdsError& e) {
    spdlog::error("DDS: {}", e.what());
    return 1;
  } catch (const pool::store::StoreError& e) {
    // Nothing is published that is not stored: stop rather than go on without the file.
    spdlog::error("--db {}: {}", db_path, e.what());
    return 1;
  }
  return 0;
}
