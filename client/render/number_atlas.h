// The ball-number atlas: the numbers 1–15 in a 4 × 4 grid of cells (cell 0, the cue ball, empty).
#pragma once

#include "client/render/text_bitmap.h"

namespace pool::render {

/// Cells per row and per column of the atlas.
inline constexpr int kNumberAtlasCells = 4;
/// Side of one cell, pixels.
inline constexpr int kNumberCellPixels = 128;

/// Draws the atlas: cell k (row k / 4, column k % 4, top-left first) holds the number k.
TextBitmap numberAtlas(const TextRasterizer& text);

}  // namespace pool::render
