// Builds the ball-number atlas from individually rasterised cells.
#include "client/render/number_atlas.h"

#include <string>

namespace pool::render {

TextBitmap numberAtlas(const TextRasterizer& text) {
  constexpr int side = kNumberAtlasCells * kNumberCellPixels;
  TextBitmap atlas{side, side, std::vector<std::uint8_t>(static_cast<std::size_t>(side * side), 0)};
  for (int id = 1; id < kNumberAtlasCells * kNumberAtlasCells; ++id) {
    const TextBitmap cell =
        text.draw({std::to_string(id)}, kNumberCellPixels, kNumberCellPixels, 96.0f);
    const int x0 = (id % kNumberAtlasCells) * kNumberCellPixels;
    const int y0 = (id / kNumberAtlasCells) * kNumberCellPixels;
    for (int y = 0; y < kNumberCellPixels; ++y) {
      for (int x = 0; x < kNumberCellPixels; ++x) {
        atlas.coverage[static_cast<std::size_t>((y0 + y) * side + x0 + x)] = cell.at(x, y);
      }
    }
  }
  return atlas;
}

}  // namespace pool::render
