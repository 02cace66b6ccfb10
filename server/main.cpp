// pool-server: the authoritative 8-ball match server; wires the match logic to Cyclone DDS.
#include <signal.h>
#include <spdlog/sinks/stdout_color_sinks.h>
#include <spdlog/spdlog.h>

#include <atomic>

#include "match/match_registry.h"
#include "match/table_kit.h"
#include "net/dds_error.h"
#include "net/messages.h"
#include "server_bus.h"
#include "server_config.h"
#include "server_loop.h"

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
  options.protocol_version = pool::net::kProtocolVersion;
  return options;
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
  MatchRegistry registry(registryOptions(config), *kit);
  for (int i = 0; i < config.tables; ++i) registry.open();
  try {
    ServerBus bus(config.domain);
    ServerLoop loop(config, registry, bus);
    spdlog::info("server {} on domain {}: {} tables, {} Hz{}", registry.serverId(), config.domain,
                 config.tables, config.snapshot_hz, config.fast ? ", unpaced" : "");
    loop.run(g_stop);
    spdlog::info("shutting down");
    loop.disposeAll();
  } catch (const pool::net::DdsError& e) {
    spdlog::error("DDS: {}", e.what());
    return 1;
  }
  return 0;
}
