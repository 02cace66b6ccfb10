// The game kit's loaded table: one load gives the spec, the geometry, the rules' view and a target
// for every pocket; a fresh rack laid out on it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "game/loaded_table.h"
#include "game/rack_layout.h"
#include "physics/simulation.h"
#include "rules/table_context.h"

namespace pool::game {
namespace {

const LoadedTable& nineFoot() {
  static const LoadedTable table = [] {
    auto loaded = loadTable("wpa-9ft");
    if (!loaded) throw std::runtime_error(loaded.error());
    return std::move(*loaded);
  }();
  return table;
}

TEST(LoadedTable, OneLoadGivesTheSpecTheRulesViewAndATargetForEveryPocket) {
  const LoadedTable& t = nineFoot();
  // WPA equipment specifications: a 9-ft table's playing surface is 100 × 50 in (2.54 × 1.27 m).
  EXPECT_NEAR(t.spec.length, 2.54, 1e-9);
  EXPECT_NEAR(t.spec.width, 1.27, 1e-9);
  EXPECT_NEAR(t.halfLength(), 1.27, 1e-9);
  EXPECT_NEAR(t.halfWidth(), 0.635, 1e-9);
  // WPA: a 2¼ in ball (57.15 mm).
  EXPECT_NEAR(t.radius(), 0.028575, 1e-9);
  EXPECT_EQ(t.context.holes.size(), t.geometry.holes.size());
  // The head string is a quarter of the length from the head cushion (WPA definitions).
  EXPECT_NEAR(t.headStringX(), -t.halfLength() / 2, 1e-9);

  // Six pockets, named as calls name them, four of them corners.
  ASSERT_EQ(t.pockets.size(), 6u);
  const auto& names = rules::pocketNames();
  int corners = 0;
  for (const auto& p : t.pockets) {
    EXPECT_NE(std::find(names.begin(), names.end(), p.name), names.end()) << p.name;
    EXPECT_EQ(pocketIndex(t, p.name), &p - t.pockets.data());
    corners += p.corner ? 1 : 0;
  }
  EXPECT_EQ(corners, 4);
  EXPECT_EQ(pocketIndex(t, "no_such_pocket"), -1);
}

TEST(LoadedTable, EachTargetsMouthIsAtTheRailsAndItsHoleBeyondItOutward) {
  const LoadedTable& t = nineFoot();
  for (const auto& p : t.pockets) {
    SCOPED_TRACE(p.name);
    EXPECT_NEAR(p.outward.norm(), 1.0, 1e-9);
    // Outward leads away from the table's centre, and the hole lies beyond the mouth along it.
    EXPECT_GT(p.outward.dot(p.mouth), 0.0);
    EXPECT_GT((p.hole - p.mouth).dot(p.outward), 0.0);
    // The mouth lies at the cushion line: within a pocket mouth (13 cm, the side pocket's, the
    // spec's widest opening) of the playing surface's edge.
    const double from_edge =
        std::min(t.halfLength() - std::abs(p.mouth.x()), t.halfWidth() - std::abs(p.mouth.y()));
    EXPECT_LT(std::abs(from_edge), 0.13);
    // A corner's outward runs along the diagonal of its corner (both components, ±45° ± 15°); a
    // side pocket's straight across the table (along ±y).
    if (p.corner) {
      EXPECT_GT(std::abs(p.outward.x()), std::cos(60.0 * M_PI / 180.0));
      EXPECT_GT(std::abs(p.outward.y()), std::cos(60.0 * M_PI / 180.0));
    } else {
      EXPECT_GT(std::abs(p.outward.y()), std::cos(5.0 * M_PI / 180.0));
    }
  }
}

TEST(LoadedTable, AMissingTableIsOneLineNamingIt) {
  const auto loaded = loadTable("no-such-table");
  ASSERT_FALSE(loaded);
  EXPECT_EQ(loaded.error().rfind("table no-such-table: ", 0), 0u) << loaded.error();
  EXPECT_EQ(loaded.error().find('\n'), std::string::npos) << loaded.error();
  EXPECT_FALSE(loadSharedTable("no-such-table"));
}

TEST(RackLayout, SixteenBallsAtRestAndTheCueBallJustBehindTheHeadString) {
  const LoadedTable& t = nineFoot();
  const auto balls = rackLayout(t, 3);
  ASSERT_EQ(balls.size(), 16u);
  for (int id = 0; id < 16; ++id) EXPECT_EQ(balls[static_cast<std::size_t>(id)].id, id);
  const auto& spots = t.context.spots;
  EXPECT_DOUBLE_EQ(balls[0].pos.x(), spots.head_spot.x() - kBreakCueSetback);
  EXPECT_LT(balls[0].pos.x(), spots.head_string_x);
  EXPECT_TRUE(physics::checkPlacement(balls, t.geometry, t.spec.params).ok());
  EXPECT_NE(rackLayout(t, 4)[5].pos, balls[5].pos);  // another seed, another order
}

}  // namespace
}  // namespace pool::game
