// Reads the stored shot and builds the scenario ShotRunner ran: only balls on the table go in.
#include "server/sim/stored_shot.h"

#include <filesystem>

#include "game/loaded_table.h"
#include "rules/game_rules.h"
#include "server/store/match_store.h"

namespace pool::sim {

Result<scenario::Scenario> storedShotScenario(const std::string& db, const std::string& match,
                                              std::uint32_t shot) {
  using Out = Result<scenario::Scenario>;
  std::error_code ec;
  if (!std::filesystem::exists(db, ec)) return Out::fail("--db " + db + ": no such file");
  auto store = store::MatchStore::open(db);
  if (!store) return Out::fail("--db " + store.error());
  try {
    const std::string table = (*store)->tableOf(match);
    if (table.empty()) return Out::fail("--match " + match + ": no such match in " + db);
    const auto stored_match = (*store)->match(match);
    const rules::Game game = stored_match ? stored_match->settings.game : rules::Game::EightBall;
    for (const auto& stored : (*store)->shots(match)) {
      const server::ShotRecord& r = stored.record;
      if (!r.shoots || r.shot_number != shot) continue;
      auto kit = game::loadSharedTable(table);
      if (!kit) return Out::fail(kit.error());
      scenario::Scenario out;
      out.spec = (*kit)->spec;
      out.geometry = (*kit)->geometry;
      for (const auto& b : r.before) {
        if (physics::onTable(b.state)) out.balls.push_back(b);
      }
      out.shot = r.command.cue;
      // The ball the server struck: the cue ball, or in three-cushion the shooter's own.
      out.shot.ball = rules::cueBallFor({game, {}, {}}, r.state);
      return Out::ok(std::move(out));
    }
  } catch (const store::StoreError& e) {
    return Out::fail("--db " + db + ": " + e.what());
  }
  return Out::fail("--shot " + std::to_string(shot) + ": match " + match + " has no such shot");
}

}  // namespace pool::sim
