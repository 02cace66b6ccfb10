// Test helpers for the rules fed with real physics: a scenario's shot simulated, as the referee
// receives it.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "rules/shot.h"
#include "rules/table_context.h"
#include "scenario/scenario.h"

namespace pool::rules::test {

// A scenario's shot, simulated, as the referee receives it.
struct Played {
  TableContext table;
  Shot shot;
};

inline Played play(const scenario::Scenario& scene, Intent intent) {
  auto outcome = scenario::runScenario(scene);
  EXPECT_TRUE(outcome) << outcome.error();
  Played played{tableContext(scene.spec, scene.geometry), {}};
  played.shot.before = scene.balls;
  played.shot.intent = std::move(intent);
  if (outcome) {
    EXPECT_FALSE(outcome->truncated);
    played.shot.events = outcome->events;
    played.shot.after = outcome->balls;
  }
  return played;
}

inline scenario::Scenario parsed(const std::string& json) {
  auto scene = scenario::parseScenario(json);
  EXPECT_TRUE(scene) << scene.error();
  return scene ? *scene : scenario::Scenario{};
}

}  // namespace pool::rules::test
