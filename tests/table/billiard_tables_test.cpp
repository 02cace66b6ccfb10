// The snooker and three-cushion tables against their governing bodies' figures: playing areas,
// marks, spots, ball sizes and masses, and the carom table's four whole cushions.
#include <gtest/gtest.h>

#include <cmath>

#include "table/rack.h"
#include "table/snooker_spots.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::table {
namespace {

TableSpec load(const char* name) {
  auto s = loadTableSpec(name);
  EXPECT_TRUE(s) << s.error();
  return s ? *s : TableSpec{};
}

constexpr double kInch = 0.0254;

// Official Rules of Snooker (WPBSA), Section 1, Equipment. Figures are nominal; the rules' own
// tolerances (±13 mm on the playing area, ±0.05 mm on a ball) are far wider than the 1e-9 m here,
// which only absorbs the spec's decimal conversion.
TEST(SnookerTable, PlayingAreaAndBallsAreTheRulesFigures) {
  const TableSpec s = load("snooker-12ft");
  // 1(a): 11 ft 8½ in × 5 ft 10 in (3569 mm × 1778 mm).
  EXPECT_NEAR(s.length, 3.569, 1e-9);
  EXPECT_NEAR(s.width, 1.778, 1e-9);
  EXPECT_NEAR(s.length, (11 * 12 + 8.5) * kInch, 0.0005);  // the imperial figure, to 0.5 mm
  EXPECT_NEAR(s.width, (5 * 12 + 10) * kInch, 0.0005);
  // 2: a diameter of 52.5 mm.
  EXPECT_NEAR(2.0 * s.params.ball_radius, 0.0525, 1e-9);
  // 1(c): six pockets, four at the corners and one at the middle of each long side.
  const TableGeometry g = buildTableGeometry(s);
  ASSERT_EQ(g.holes.size(), 6u);
  int middle = 0;
  for (const PocketHole& h : g.holes) middle += std::abs(h.centre.x()) < 1e-12 ? 1 : 0;
  EXPECT_EQ(middle, 2);
  // Each pocket's mouth takes a ball with room to spare, and is narrower than a pool table's
  // (WPA: corner 4.5–4.625 in), as snooker's templates are cut for the smaller ball.
  EXPECT_GT(s.corner.mouth, 2.0 * s.params.ball_radius);
  EXPECT_LT(s.corner.mouth, 4.5 * kInch);
}

TEST(SnookerTable, TheMarksAndSpotsAreWhereTheRulesPutThem) {
  const TableSpec s = load("snooker-12ft");
  const auto spots = snookerSpotsFor(s);
  ASSERT_TRUE(spots);
  const double bottom = -3.569 / 2.0;  // face of the bottom (baulk) cushion, x
  const double top = 3.569 / 2.0;      // face of the top cushion
  // 1(d): the baulk line 29 in (737 mm) from the face of the bottom cushion.
  EXPECT_NEAR(spots->baulk_x - bottom, 0.737, 1e-9);
  // 1(e): the D, radius 11½ in (292 mm), centred on the middle of the baulk line.
  EXPECT_NEAR(spots->d_radius, 0.292, 1e-9);
  // 1(f)(i): the black spot 12¾ in (324 mm) from the face of the top cushion.
  EXPECT_NEAR(top - spots->black.x(), 0.324, 1e-9);
  EXPECT_NEAR(spots->black.y(), 0.0, 1e-12);
  // (ii) the blue midway between the two cushions' faces; (iii) the pink midway between the
  // blue and the face of the top cushion; (iv) the brown at the middle of the baulk line.
  EXPECT_NEAR(spots->blue.x(), (bottom + top) / 2.0, 1e-12);
  EXPECT_NEAR(spots->pink.x(), (spots->blue.x() + top) / 2.0, 1e-12);
  EXPECT_NEAR((spots->brown - Eigen::Vector2d(spots->baulk_x, 0.0)).norm(), 0.0, 1e-12);
  // The corners of the D: viewed from the baulk end (looking toward +x, so right is −y), the
  // yellow on the right and the green on the left.
  EXPECT_NEAR((spots->yellow - Eigen::Vector2d(spots->baulk_x, -0.292)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((spots->green - Eigen::Vector2d(spots->baulk_x, 0.292)).norm(), 0.0, 1e-12);
  // In the D: on the baulk line's side of it and within the radius of the brown spot.
  EXPECT_TRUE(inTheD(*spots, spots->brown + Eigen::Vector2d(-0.29, 0.0)));
  EXPECT_TRUE(inTheD(*spots, spots->yellow));
  EXPECT_FALSE(inTheD(*spots, spots->brown + Eigen::Vector2d(0.01, 0.0)));    // above the line
  EXPECT_FALSE(inTheD(*spots, spots->brown + Eigen::Vector2d(-0.21, 0.21)));  // 297 mm away
  // A pool table has no snooker marks.
  EXPECT_FALSE(snookerSpotsFor(load("wpa-9ft")));
}

// UMB, World Rules of Carom Billiard: equipment (billiard, cushion, cloth; balls) and the spots.
TEST(CaromTable, MatchTableAndBallsAreTheUmbFigures) {
  const TableSpec s = load("carom-match");
  // The free playing surface 2.84 m × 1.42 m (±5 mm).
  EXPECT_NEAR(s.length, 2.84, 1e-9);
  EXPECT_NEAR(s.width, 1.42, 1e-9);
  // Cushions 37 mm high at their frontmost point (±1 mm); a frame 12.5 cm wide (±1 cm).
  EXPECT_NEAR(s.params.cushion_height, 0.037, 1e-9);
  EXPECT_NEAR(s.rail_width, 0.125, 1e-9);
  // Balls 61 to 61.5 mm across and 205 to 220 g.
  EXPECT_GE(2.0 * s.params.ball_radius, 0.061);
  EXPECT_LE(2.0 * s.params.ball_radius, 0.0615);
  EXPECT_GE(s.params.ball_mass, 0.205);
  EXPECT_LE(s.params.ball_mass, 0.220);
  // The nose is between the ball's centre and its top, so a cushion pushes a ball down onto the
  // slate and never lifts it over (37 mm on a 61.5 mm ball: 0.60 of the diameter).
  EXPECT_GT(s.params.cushion_height, s.params.ball_radius);
  EXPECT_LT(s.params.cushion_height, 2.0 * s.params.ball_radius);
  // The three spots on the long string: the top spot and the bottom spot each a quarter of the
  // length (71 cm) from their short cushions, and the centre spot.
  const Spots spots = spotsFor(s);
  EXPECT_NEAR(s.length / 2.0 - spots.foot_spot.x(), 0.71, 1e-9);
  EXPECT_NEAR(spots.head_spot.x() + s.length / 2.0, 0.71, 1e-9);
  EXPECT_NEAR(spots.centre_spot.norm(), 0.0, 1e-12);
}

TEST(CaromTable, FourWholeCushionsAndNoPocket) {
  const TableSpec s = load("carom-match");
  EXPECT_FALSE(s.pockets);
  const TableGeometry g = buildTableGeometry(s);
  EXPECT_TRUE(g.holes.empty());
  ASSERT_EQ(g.noses.size(), 4u);
  // The noses run corner to corner round the playing surface, each facing the table's centre.
  double perimeter = 0.0;
  for (const NoseSegment& n : g.noses) {
    perimeter += (n.b - n.a).norm();
    const Eigen::Vector2d mid = (n.a + n.b) / 2.0;
    EXPECT_LT(n.normal.dot(mid), 0.0) << n.name;
    for (const Eigen::Vector2d& end : {n.a, n.b}) {
      EXPECT_NEAR(std::abs(end.x()), s.length / 2.0, 1e-12) << n.name;
      EXPECT_NEAR(std::abs(end.y()), s.width / 2.0, 1e-12) << n.name;
    }
  }
  EXPECT_NEAR(perimeter, 2.0 * (s.length + s.width), 1e-12);
  const auto loaded = loadTableGeometry(s);
  ASSERT_TRUE(loaded) << loaded.error();
  EXPECT_TRUE(loaded->holes.empty());
}

TEST(CaromTable, ASpecWithoutPocketsDescribesNone) {
  auto spec = parseTableSpec(
      R"({"length": 2.84, "width": 1.42, "cushion_width": 0.05, "rail_width": 0.125,
          "slate_thickness": 0.045, "pockets": false,
          "corner": {"mouth": 0.1, "jaw_angle_deg": 142, "hole_radius": 0.07, "hole_offset": 0.04}})",
      "spec.json", ".", "x");
  ASSERT_FALSE(spec);
  EXPECT_EQ(spec.error(), "corner: a table without pockets has no pocket spec");
  spec = parseTableSpec(R"({"length": 2.84, "width": 1.42, "cushion_width": 0.05,
      "rail_width": 0.125, "slate_thickness": 0.045, "pockets": "no"})",
                        "spec.json", ".", "x");
  ASSERT_FALSE(spec);
  EXPECT_EQ(spec.error(), "pockets: must be true or false");
}

}  // namespace
}  // namespace pool::table
