// Model selection: every name the spec accepts makes a model, and an unknown one is refused.
#include <gtest/gtest.h>

#include "fixtures.h"
#include "physics/contact_models.h"
#include "table/contact_models.h"

namespace pool::physics::test {
namespace {

TEST(ContactModels, EveryKnownNameMakesItsModel) {
  for (const auto pair : table::contactPairs()) {
    for (const auto name : table::knownModels(pair)) {
      table::ContactModels names;
      ASSERT_TRUE(table::setModel(names, pair, name).ok());
      const auto made = makeContactModels(names, table::PhysicsParams{});
      ASSERT_TRUE(made) << pair << " " << name << ": " << made.error();
      EXPECT_TRUE(made->cloth && made->ball_ball && made->cushion && made->slate);
    }
  }
}

TEST(ContactModels, AnUnknownNameIsRefusedBeforeAnyBallIsPlaced) {
  table::TableSpec spec = openSpec();
  spec.models.ball_cushion = "bouncy";  // set in code, past the spec parser's check
  Simulation sim(spec, openGeometry(spec));
  const auto placed = sim.setBalls({ballAt(0, 0.0, 0.0)});
  ASSERT_FALSE(placed);
  EXPECT_EQ(placed.error(), "models.ball_cushion: unknown model 'bouncy'");
}

// The same bank shot on each cushion model: the choice reaches the event loop (Han's impulse
// ends the nose slip at zero, Mathavan's lets the slate act too, so the rebounds differ).
TEST(ContactModels, TheSpecsCushionModelIsTheOneThatRuns) {
  auto rebound = [](const std::string& model) {
    table::TableSpec spec = realTable().spec;
    spec.models.ball_cushion = model;
    CueShot shot;
    shot.yaw = 60 * kDeg;
    shot.speed = 1.5;
    shot.speed_is_ball = true;
    Simulation sim(spec, realTable().geometry);
    EXPECT_TRUE(sim.setBalls({ballAt(0, 0.2, 0.35)}));
    SimOptions opt;
    opt.max_time = 0.5;
    return ballById(*sim.shoot(shot, opt), 0).pos;
  };
  EXPECT_GT((rebound("han2005") - rebound("mathavan2010")).norm(), 1e-3);
}

}  // namespace
}  // namespace pool::physics::test
