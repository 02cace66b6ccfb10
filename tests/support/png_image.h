// Test helpers for rendered PNGs: decoding, colour classes (lit shades, white, black) and counts
// of matching pixels in regions.
#pragma once

#include <stb_image.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace pool::client::test {

using Rgb = std::array<double, 3>;  ///< 0..255 (pixels) or 0..1 (palette colours)

/// An RGB image decoded from a PNG (empty when the file could not be read).
struct Image {
  int width = 0;
  int height = 0;
  std::vector<Rgb> pixels;  ///< row-major, top row first, 0..255

  const Rgb& at(int x, int y) const {
    return pixels[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                  static_cast<std::size_t>(x)];
  }
};

inline Image loadPng(const std::string& path) {
  Image image;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &image.width, &image.height, &channels, 3);
  if (!data) return image;
  const auto n = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  for (std::size_t i = 0; i < n; ++i)
    image.pixels.push_back({double(data[3 * i]), double(data[3 * i + 1]), double(data[3 * i + 2])});
  stbi_image_free(data);
  return image;
}

/// True when `p` is a lit shade of `colour`: same hue and saturation (direction in RGB), its
/// brightest channel at least `min_bright`.
inline bool shadeOf(const Rgb& p, const Rgb& colour, double min_bright = 40.0) {
  double dot = 0, pp = 0, cc = 0;
  for (int i = 0; i < 3; ++i) {
    dot += p[i] * colour[i];
    pp += p[i] * p[i];
    cc += colour[i] * colour[i];
  }
  const double brightest = std::max({p[0], p[1], p[2]});
  return brightest >= min_bright && dot / std::sqrt(pp * cc) > 0.997;
}

inline bool isWhite(const Rgb& p) {
  return std::min({p[0], p[1], p[2]}) > 190.0 &&
         std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) < 30.0;
}

inline bool isBlack(const Rgb& p) {
  return std::max({p[0], p[1], p[2]}) < 20.0;
}

/// Pixels of `image` (optionally within columns [x0, x1)) satisfying `pred`.
template <class Pred>
int count(const Image& image, Pred pred, int x0 = 0, int x1 = -1) {
  if (x1 < 0) x1 = image.width;
  int n = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = x0; x < x1; ++x) {
      if (pred(image.at(x, y))) ++n;
    }
  }
  return n;
}

/// Pixels satisfying `pred` within `radius` pixels of (cx, cy), clipped to the image.
template <class Pred>
int countInDisc(const Image& image, double cx, double cy, double radius, Pred pred) {
  int n = 0;
  const int r = static_cast<int>(std::ceil(radius));
  for (int y = static_cast<int>(cy) - r; y <= static_cast<int>(cy) + r; ++y) {
    for (int x = static_cast<int>(cx) - r; x <= static_cast<int>(cx) + r; ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      const double dx = x + 0.5 - cx, dy = y + 0.5 - cy;
      if (dx * dx + dy * dy <= radius * radius && pred(image.at(x, y))) ++n;
    }
  }
  return n;
}

/// Ball colours 1–8 as the palette defines them (stripes 9–15 carry those of n − 8 as a band).
constexpr std::array<Rgb, 8> kBallColours{{
    {0.98, 0.80, 0.05},  // 1 yellow
    {0.05, 0.15, 0.80},  // 2 blue
    {0.85, 0.05, 0.05},  // 3 red
    {0.40, 0.10, 0.60},  // 4 purple
    {1.00, 0.45, 0.02},  // 5 orange
    {0.02, 0.55, 0.08},  // 6 green
    {0.45, 0.04, 0.10},  // 7 maroon
    {0.03, 0.03, 0.03},  // 8 black
}};

/// True when pixel `p` shows ball `id`'s own colour: white for the cue ball, black for the 8,
/// the (band) colour for the others.
inline bool ballColour(int id, const Rgb& p) {
  if (id == 0) return isWhite(p);
  if (id == 8) return isBlack(p);
  return shadeOf(p, kBallColours[static_cast<std::size_t>((id - 1) % 8)]);
}

/// A light neutral grey: white in dim light.
inline bool isLightNeutral(const Rgb& p) {
  return std::min({p[0], p[1], p[2]}) > 70.0 &&
         std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]}) < 25.0;
}

/// As ballColour, for a ball that may lie outside the lamps' pools of light, in the hall's dim
/// light: the cue ball a light neutral grey, the coloured balls their hue from a lower brightness.
inline bool ballColourInAnyLight(int id, const Rgb& p) {
  if (id == 0) return isLightNeutral(p);
  if (id == 8) return isBlack(p);
  return shadeOf(p, kBallColours[static_cast<std::size_t>((id - 1) % 8)], 24.0);
}

}  // namespace pool::client::test
