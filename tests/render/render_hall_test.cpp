// The pool hall and the table's furniture in real frames, and their generated assets: the
// committed OBJs are what pool-hallgen writes and load through assimp; the hall's floor shows
// round the table in the overview and its papered wall and scoreboard behind it in the aiming
// view; the apron and legs stand under the rails; a pocket is a dark hole in a leather rim, its
// liner going down under the slate. Positions come from the hall's layout and the table spec; the
// sidecar's camera projects them.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

#include "client/render/hall_assets.h"
#include "client/render/hall_layout.h"
#include "client/render/mesh_asset.h"
#include "client/render/table_dressing.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/screenshot_fixture.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

namespace hall = render::hall;

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

std::set<std::string> partNames(const std::string& relative) {
  const auto parts = render::loadMeshAsset(relative);
  EXPECT_TRUE(static_cast<bool>(parts)) << parts.error();
  std::set<std::string> names;
  if (!parts) return names;
  for (const auto& p : *parts) {
    EXPECT_FALSE(p.mesh.positions.empty()) << relative << ": " << p.name;
    EXPECT_EQ(p.mesh.positions.size(), p.mesh.normals.size()) << relative << ": " << p.name;
    names.insert(p.name);
  }
  return names;
}

TEST(HallAssetsTest, CommittedRoomIsTheGeneratorsOutputAndLoads) {
  const auto obj = render::roomObj();
  ASSERT_TRUE(static_cast<bool>(obj)) << obj.error();
  EXPECT_EQ(fileText(std::string(POOL_SOURCE_DIR) + "/assets/hall/room.obj"), *obj)
      << "regenerate: build/bin/pool-hallgen room -o assets/hall/room.obj";
  const auto names = partNames("hall/room.obj");
  for (const char* part : {"floor", "ceiling", "wainscot", "wallpaper", "stool_seat", "rack_wood",
                           "rack_cue_shaft", "board", "bead_light", "gilt", "canvas_sky"}) {
    EXPECT_TRUE(names.count(part)) << part;
  }
}

TEST(HallAssetsTest, EachTablesDressingIsTheGeneratorsOutputAndLoads) {
  for (const char* table : {"wpa-7ft", "wpa-8ft", "wpa-9ft"}) {
    const auto obj = render::dressingObj(table);
    ASSERT_TRUE(static_cast<bool>(obj)) << obj.error();
    EXPECT_EQ(fileText(std::string(POOL_SOURCE_DIR) + "/assets/hall/" + table + ".obj"), *obj)
        << "regenerate: build/bin/pool-hallgen " << table << " -o assets/hall/" << table << ".obj";
    EXPECT_EQ(partNames(std::string("hall/") + table + ".obj"),
              (std::set<std::string>{"rail_top", "rail_edge", "apron", "underside", "leg",
                                     "pocket_liner", "pocket_rim"}))
        << table;
  }
}

TEST(HallAssetsTest, AnUnknownTableIsRefused) {
  EXPECT_FALSE(static_cast<bool>(render::dressingObj("no-such-table")));
}

/// Mean colour of the 5 × 5 pixels around pixel `px`.
std::array<double, 3> meanAround(const Image& image, glm::vec3 px) {
  std::array<double, 3> sum{0, 0, 0};
  for (int dy = -2; dy <= 2; ++dy) {
    for (int dx = -2; dx <= 2; ++dx) {
      const auto& p = image.at(int(px.x) + dx, int(px.y) + dy);
      for (int c = 0; c < 3; ++c) sum[c] += p[c] / 25.0;
    }
  }
  return sum;
}

/// Wood, leather, paper: warm colours (red over blue, brighter than the void's grey-blue).
bool warm(const std::array<double, 3>& c) {
  return c[0] > c[2] + 6.0 && c[0] >= c[1] && luminance(c) > 12.0;
}

class HallTest : public ScreenshotInfoTest {
 protected:
  /// The pixel of `p`, which must be in the frame.
  glm::vec3 pixelOf(glm::vec3 p) const {
    const glm::vec3 px = camera_.pixel(p);
    EXPECT_TRUE(camera_.inside(px, 4.0f)) << p.x << " " << p.y << " " << p.z;
    return px;
  }
};

table::TableGeometry nineFoot() {
  auto spec = table::loadTableSpec("wpa-9ft");
  EXPECT_TRUE(static_cast<bool>(spec));
  return table::buildTableGeometry(*spec);
}

TEST_F(HallTest, TheOverviewShowsTheFloorRoundTheTableAndTheApronUnderItsRails) {
  const Image image = view("--scene rack");
  ASSERT_FALSE(image.pixels.empty());
  const auto geometry = nineFoot();
  const auto half_length = float(geometry.length / 2), half_width = float(geometry.width / 2);
  // The floor beyond both ends of the table: oak planks, lit by the hall.
  for (const float x : {-(half_length + 0.55f), half_length + 0.55f}) {
    const auto c = meanAround(image, pixelOf({x, 0.0f, hall::kFloorZ}));
    EXPECT_TRUE(warm(c)) << "floor at x " << x << ": " << c[0] << " " << c[1] << " " << c[2];
  }
  // The near long side's apron, halfway down from the rail, beside the trough (which hangs in
  // front of the middle): wood, where the table used to end at the rail.
  const float outer_y = -(half_width + 0.05f + 0.1f);
  for (const float x : {-0.9f, 0.9f}) {
    const auto c = meanAround(image, pixelOf({x, outer_y, hall::kApronBottom * 0.5f}));
    EXPECT_TRUE(warm(c)) << "apron at x " << x << ": " << c[0] << " " << c[1] << " " << c[2];
  }
}

TEST_F(HallTest, TheAimingViewShowsThePaperedWallAndTheScoreboardBehindTheTable) {
  const Image image = view("--scene aim");
  ASSERT_FALSE(image.pixels.empty());
  // The aiming view of the break looks down the table at the foot wall.
  const hall::WallPiece& board = hall::kWallPieces[1];
  ASSERT_STREQ(board.name, "scoreboard");
  const auto paper = meanAround(image, pixelOf({hall::kHalfX, 0.0f, board.centre.z}));
  EXPECT_TRUE(warm(paper)) << paper[0] << " " << paper[1] << " " << paper[2];
  EXPECT_GT(paper[0], 1.5 * paper[1]) << "burgundy paper";
  // The scoreboard's dark board between its two rows of beads, far less red than the paper.
  const glm::vec3 on_board = board.centre + glm::vec3(-0.04f, 0.3f * board.size.x, 0.0f);
  const auto dark = meanAround(image, pixelOf(on_board));
  EXPECT_LT(dark[0] + 15.0, paper[0]) << dark[0] << " " << dark[1] << " " << dark[2];
  // The wainscot under the paper, where the wall meets the floor.
  const auto panel = meanAround(image, pixelOf({hall::kHalfX, -0.3f, hall::kWainscotTop - 0.2f}));
  EXPECT_TRUE(warm(panel)) << panel[0] << " " << panel[1] << " " << panel[2];
}

TEST_F(HallTest, APocketIsADarkHoleInALeatherRimWithItsLinerGoingDown) {
  // From above: the six pockets of the spread scene's table.
  const Image image = view("--scene top");
  ASSERT_FALSE(image.pixels.empty());
  const auto geometry = nineFoot();
  for (const auto& hole : geometry.holes) {
    const glm::vec3 centre(float(hole.centre.x()), float(hole.centre.y()), 0.0f);
    // Deep inside: the liner's cup, nearly black.
    const auto inside = meanAround(image, pixelOf(centre - glm::vec3(0, 0, render::kLinerDepth)));
    EXPECT_LT(luminance(inside), 20.0) << hole.name;
    // The rim on the rail top round the cut: dark leather. Behind a corner pocket (away from
    // the table's middle); beside a side pocket, along the rail (it cuts the rail nearly to its
    // outer edge).
    const bool side = std::abs(centre.x) < 0.1f;
    const glm::vec2 out =
        side ? glm::vec2(1.0f, 0.0f) : glm::normalize(glm::vec2(centre.x, centre.y));
    const float r = float(hole.radius) + 0.5f * render::kRimWidth;
    const glm::vec3 rim = centre + glm::vec3(out * r, 0.042f);
    const auto leather = meanAround(image, pixelOf(rim));
    EXPECT_LT(luminance(leather), 40.0) << hole.name;
    // The wood of the long rail's top 20 cm along from the pocket (toward the middle of the
    // table's length, between the diamonds) is clearly brighter.
    const float along = centre.x > 0.1f ? -0.2f : 0.2f;
    const float rail_middle = float(geometry.width / 2) + 0.05f + 0.05f;  // cushion, half a rail
    const glm::vec3 wood(centre.x + along, centre.y > 0 ? rail_middle : -rail_middle, 0.042f);
    EXPECT_GT(luminance(meanAround(image, pixelOf(wood))), luminance(leather) + 8.0) << hole.name;
  }
}

TEST_F(HallTest, TheLightPresetDrawsTheSameSceneAtLowerResolution) {
  const Image full = view("--scene aim");
  const Image light = view("--scene aim --quality light");
  ASSERT_EQ(full.width, light.width);
  ASSERT_EQ(full.height, light.height);
  // Same picture: the wall, the felt and the cue ball in the same places (mean colours over
  // patches agree), only softer: edges differ pixel by pixel.
  double differences = 0;
  int patches = 0;
  for (int y = 40; y < full.height - 40; y += 80) {
    for (int x = 40; x < full.width - 40; x += 80) {
      const auto a = meanAround(full, glm::vec3(x, y, 1));
      const auto b = meanAround(light, glm::vec3(x, y, 1));
      differences += std::abs(luminance(a) - luminance(b));
      ++patches;
    }
  }
  EXPECT_LT(differences / patches, 6.0);
  std::size_t changed = 0;
  for (std::size_t i = 0; i < full.pixels.size(); ++i) {
    for (int c = 0; c < 3; ++c) {
      if (std::abs(full.pixels[i][c] - light.pixels[i][c]) > 3.0) {
        ++changed;
        break;
      }
    }
  }
  EXPECT_GT(changed, full.pixels.size() / 100) << "the light preset drew at full resolution";
}

}  // namespace
}  // namespace pool::client::test
