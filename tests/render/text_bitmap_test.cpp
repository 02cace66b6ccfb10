// Text rasterisation: ink where text is drawn, none elsewhere, word wrapping, a missing font.
#include "client/render/text_bitmap.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "client/render/number_atlas.h"
#include "support/display_check.h"

namespace pool::render {
namespace {

int ink(const TextBitmap& b, int x0, int y0, int w, int h) {
  int n = 0;
  for (int y = y0; y < y0 + h; ++y) {
    for (int x = x0; x < x0 + w; ++x) n += b.at(x, y) > 128 ? 1 : 0;
  }
  return n;
}

TEST(TextBitmapTest, NumberAtlasHasInkInCellsOneToFifteenOnly) {
  if (!std::filesystem::exists(kFontPath)) POOL_MISSING_SETUP("fonts-dejavu-core missing");
  const TextBitmap atlas = numberAtlas(TextRasterizer());
  ASSERT_EQ(atlas.width, kNumberAtlasCells * kNumberCellPixels);
  const int cell = kNumberCellPixels;
  EXPECT_EQ(ink(atlas, 0, 0, cell, cell), 0) << "cell 0 (the cue ball) stays blank";
  for (int id = 1; id < 16; ++id) {
    const int x = (id % 4) * cell, y = (id / 4) * cell;
    EXPECT_GT(ink(atlas, x, y, cell, cell), cell * cell / 20) << "number " << id;
    // Centred: no ink touches the cell's border.
    EXPECT_EQ(ink(atlas, x, y, cell, 2) + ink(atlas, x, y + cell - 2, cell, 2), 0) << id;
  }
  // Two digits take more ink than one.
  EXPECT_GT(ink(atlas, (11 % 4) * cell, (11 / 4) * cell, cell, cell),
            ink(atlas, (1 % 4) * cell, (1 / 4) * cell, cell, cell));
}

TEST(TextBitmapTest, LongLinesShrinkToFitTheCell) {
  if (!std::filesystem::exists(kFontPath)) POOL_MISSING_SETUP("fonts-dejavu-core missing");
  const TextRasterizer text;
  const TextBitmap b = text.draw({"Signs point to yes"}, 100, 40, 40.0f);
  EXPECT_GT(ink(b, 0, 0, 100, 40), 50);
  EXPECT_EQ(ink(b, 0, 0, 2, 40) + ink(b, 98, 0, 2, 40), 0) << "nothing cut at the sides";
}

TEST(TextBitmapTest, WrapWordsBreaksAtSpaces) {
  EXPECT_EQ(wrapWords("Reply hazy, try again", 10),
            (std::vector<std::string>{"Reply", "hazy, try", "again"}));
  EXPECT_EQ(wrapWords("Indubitably", 4), (std::vector<std::string>{"Indubitably"}));
  EXPECT_TRUE(wrapWords("   ", 4).empty());
}

TEST(TextBitmapTest, AMissingFontIsAClearError) {
  try {
    TextRasterizer text("/nonexistent/font.ttf");
    FAIL() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("/nonexistent/font.ttf"), std::string::npos);
  }
}

}  // namespace
}  // namespace pool::render
