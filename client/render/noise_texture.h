// A tiling value-noise image for the felt's fibre and the wood's grain.
#pragma once

#include <cstdint>

#include "client/render/text_bitmap.h"

namespace pool::render {

/// A `size` × `size` image of smooth value noise over a `cells` × `cells` lattice that wraps at
/// the edges (so it tiles), values spread over 0..255. Deterministic for a given seed.
TextBitmap valueNoise(int size, int cells, std::uint32_t seed);

}  // namespace pool::render
