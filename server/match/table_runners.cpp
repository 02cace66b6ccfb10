// The shot runner of each table a server plays on, loaded on first use.
#include "server/match/table_runners.h"

#include "game/loaded_table.h"

namespace pool::server {

TableRunners::TableRunners(std::shared_ptr<ShotRunner> pool) : pool_(std::move(pool)) {}

Result<std::shared_ptr<ShotRunner>> TableRunners::forGame(rules::Game game) {
  using Out = Result<std::shared_ptr<ShotRunner>>;
  const std::string name = rules::tableOf(game, pool_->kit().spec.name);
  if (name == pool_->kit().spec.name) return Out::ok(pool_);
  if (const auto it = others_.find(name); it != others_.end()) return Out::ok(it->second);
  auto kit = game::loadSharedTable(name);
  if (!kit) return Out::fail(kit.error());
  auto runner = std::make_shared<ShotRunner>(std::move(*kit));
  others_.emplace(name, runner);
  return Out::ok(std::move(runner));
}

}  // namespace pool::server
