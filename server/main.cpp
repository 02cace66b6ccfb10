// pool-server: the authoritative 8-, 9- and 10-ball match server; wires the match logic to Cyclone
// DDS.
#include <signal.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <atomic>

#include "net/dds_error.h"
#include "net/server_transport.h"
#include "protocol/protocol_version.h"
#include "server/match/match_registry.h"
#include "server/match/match_replay.h"
#include "server/match/table_kit.h"
#include "server/match/token_source.h"
#include "server/server_config.h"
#include "server/server_loop.h"
#include "server/store/match_store.h"

namespace {

std::atomic<bool> g_stop{false};

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
  options.match.snapshot_hz = config.snapshot_hz;
  options.match.unpaced = config.fast;
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

/// Serves matches, resuming those of `store` and keeping every change in it.
void serve(const pool::server::ServerConfig& config,
           std::shared_ptr<const pool::server::TableKit> kit, pool::store::MatchStore& store,
           const std::string& db_path) {
  using namespace pool::server;
  store.setTable(config.table);
  RegistryOptions options = registryOptions(config);
  // The file keeps the server's id, so match ids go on where they stopped.
  if (options.server_id.empty()) options.server_id = store.serverId();
  MatchRegistry registry(options, std::move(kit));
  const int resumed = resume(registry, store);
  const int opened = registry.keepFreeTables(config.tables);
  pool::net::ServerTransport transport(config.domain);
  ServerLoop loop(config, registry, transport, &store);
  spdlog::info("server {} on domain {}: {} free tables opened, {} resumed, {} Hz{}, db {}",
               registry.serverId(), config.domain, opened, resumed, config.snapshot_hz,
               config.fast ? ", unpaced" : "", db_path);
  loop.run(g_stop);
  spdlog::info("shutting down");
  loop.disposeAll();
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
  auto kit = loadTableKit(store.tableOf(config.replay));
  if (!kit) {
    spdlog::error("--replay {}: {}", config.replay, kit.error());
    return 1;
  }
  std::vector<ShotRecord> commands;
  for (auto& shot : store.shots(config.replay)) commands.push_back(std::move(shot.record));
  const std::size_t count = commands.size();
  MatchRegistry registry(registryOptions(config), *kit);
  for (int i = 0; i < config.tables; ++i) registry.open();
  Match* target = registry.open("Replay of " + stored->id, stored->rack_seed);
  TokenSource tokens(randomSeed());
  MatchReplay replay(*stored, std::move(commands), *target, {tokens.token(), tokens.token()},
                     config.fast ? 0.0 : 1.0);
  pool::net::ServerTransport transport(config.domain);
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
  const ConfigOutcome parsed = parseConfig(argc, argv);
  if (parsed.exit_code) return *parsed.exit_code;
  const ServerConfig& config = parsed.config;
  setUpLogging(config);
  installSignalHandlers();

  auto kit = loadTableKit(config.table);
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
    serve(config, *kit, **store, db_path);
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
