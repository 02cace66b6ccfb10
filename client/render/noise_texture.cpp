// Value noise: random lattice values, smoothstep-interpolated, with the lattice wrapped to tile.
#include "client/render/noise_texture.h"

#include <vector>

namespace pool::render {

namespace {

/// A 32-bit integer hash (lowbias32), to 0..1.
double latticeValue(std::uint32_t x, std::uint32_t y, std::uint32_t seed) {
  std::uint32_t h = x * 0x9E3779B1u ^ (y + 0x7F4A7C15u) * 0x85EBCA77u ^ seed * 0xC2B2AE3Du;
  h ^= h >> 16;
  h *= 0x7FEB352Du;
  h ^= h >> 15;
  h *= 0x846CA68Bu;
  h ^= h >> 16;
  return static_cast<double>(h) / 4294967295.0;
}

double smooth(double t) {
  return t * t * (3.0 - 2.0 * t);
}

}  // namespace

TextBitmap valueNoise(int size, int cells, std::uint32_t seed) {
  TextBitmap image{size, size, std::vector<std::uint8_t>(static_cast<std::size_t>(size * size))};
  const double step = static_cast<double>(cells) / static_cast<double>(size);
  const auto wrap = [cells](int i) { return static_cast<std::uint32_t>(i % cells); };
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const double fx = x * step, fy = y * step;
      const int ix = static_cast<int>(fx), iy = static_cast<int>(fy);
      const double u = smooth(fx - ix), v = smooth(fy - iy);
      const double a = latticeValue(wrap(ix), wrap(iy), seed);
      const double b = latticeValue(wrap(ix + 1), wrap(iy), seed);
      const double c = latticeValue(wrap(ix), wrap(iy + 1), seed);
      const double d = latticeValue(wrap(ix + 1), wrap(iy + 1), seed);
      const double value = (a + (b - a) * u) * (1.0 - v) + (c + (d - c) * u) * v;
      image.coverage[static_cast<std::size_t>(y * size + x)] =
          static_cast<std::uint8_t>(value * 255.0 + 0.5);
    }
  }
  return image;
}

}  // namespace pool::render
