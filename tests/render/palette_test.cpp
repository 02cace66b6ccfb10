// The ball sets by table (pool, carom, snooker) and the snooker colours' looks.
#include "client/render/palette.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "table/table_spec.h"

namespace pool::render {
namespace {

BallSet setOf(const std::string& table) {
  const auto spec = table::loadTableSpec(table);
  EXPECT_TRUE(spec) << spec.error();
  return spec ? ballSetOf(*spec) : BallSet::Pool;
}

float luma(glm::vec3 c) {
  return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}

TEST(PaletteTest, EachTableHasItsSet) {
  EXPECT_EQ(setOf("wpa-9ft"), BallSet::Pool);
  EXPECT_EQ(setOf("carom-match"), BallSet::Carom);
  EXPECT_EQ(setOf("snooker-12ft"), BallSet::Snooker);
  EXPECT_EQ(maxBallIdOf(BallSet::Pool), 15);
  EXPECT_EQ(maxBallIdOf(BallSet::Carom), 2);
  EXPECT_EQ(maxBallIdOf(BallSet::Snooker), 21);
}

// 0 the cue ball, 1-15 the reds, 16 yellow, 17 green, 18 brown, 19 blue, 20 pink, 21 black; no
// numbers, no stripes.
TEST(PaletteTest, SnookerBallsReadApart) {
  const auto look = [](int id) { return ballLook(id, BallSet::Snooker); };
  for (int id = 0; id <= 21; ++id) {
    EXPECT_EQ(look(id).number, 0) << id;
    EXPECT_FALSE(look(id).striped) << id;
  }
  const glm::vec3 cue = look(0).colour, red = look(1).colour;
  for (int id = 2; id <= 15; ++id) EXPECT_EQ(look(id).colour, red) << id;
  EXPECT_GT(std::min({cue.r, cue.g, cue.b}), 0.85f) << "the cue ball is white";
  EXPECT_LT(std::max(red.g, red.b), 0.1f * red.r) << "a deep red";
  const glm::vec3 yellow = look(16).colour, green = look(17).colour, brown = look(18).colour;
  const glm::vec3 blue = look(19).colour, pink = look(20).colour, black = look(21).colour;
  EXPECT_GT(yellow.g, 0.6f * yellow.r);
  EXPECT_LT(yellow.b, 0.2f * yellow.r);
  EXPECT_GT(green.g, 3.0f * green.r);
  // The green apart from the cloth: darker by a third at least.
  EXPECT_LT(luma(green), 0.67f * luma(partLook("slate").colour));
  EXPECT_GT(blue.b, 3.0f * std::max(blue.r, blue.g));
  // Pink: red lightened toward white, bluish; clearly apart from the reds.
  EXPECT_GT(pink.g, 0.3f * pink.r);
  EXPECT_GT(pink.b, pink.g);
  EXPECT_GT(luma(pink), 3.0f * luma(red));
  // Brown: orange-tinged (more green than blue, more than a red has), darker than the reds'
  // red channel, lighter than the black.
  EXPECT_GT(brown.g, 2.0f * brown.b);
  EXPECT_GT(brown.g / brown.r, 3.0f * red.g / red.r);
  EXPECT_LT(brown.r, 0.7f * red.r);
  EXPECT_GT(luma(brown), 3.0f * luma(black));
  EXPECT_LT(std::max({black.r, black.g, black.b}), 0.05f);
  // Ids beyond the set: white, as an unknown ball of any set.
  EXPECT_EQ(look(22).colour, cue);
  EXPECT_EQ(ballLook(16, BallSet::Pool).colour, ballLook(0, BallSet::Pool).colour);
}

}  // namespace
}  // namespace pool::render
