// Text rasterised on the CPU with stb_truetype (DejaVu Sans Bold): ball numbers and short captions.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pool::render {

/// A single-channel coverage image (0: empty, 255: ink), top row first.
struct TextBitmap {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> coverage;

  std::uint8_t at(int x, int y) const {
    return coverage[static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                    static_cast<std::size_t>(x)];
  }
};

/// The font file used for all text (fonts-dejavu-core).
inline constexpr const char* kFontPath = "/usr/share/fonts/truetype/dejavu/DejaVuSans-Bold.ttf";

/// Loads a TrueType font once and draws strings with it. Throws std::runtime_error when the font
/// file cannot be read or parsed.
class TextRasterizer {
 public:
  explicit TextRasterizer(const std::string& font_path = kFontPath);
  ~TextRasterizer();
  TextRasterizer(const TextRasterizer&) = delete;
  TextRasterizer& operator=(const TextRasterizer&) = delete;

  /// Draws `lines` (one string per line) centred in a cell of `width` × `height` pixels, each
  /// line `pixel_height` tall; lines wider than the cell are scaled down to fit.
  TextBitmap draw(const std::vector<std::string>& lines, int width, int height,
                  float pixel_height) const;

 private:
  struct Font;
  float lineWidth(const std::string& line, float scale) const;
  void drawLine(TextBitmap& bitmap, const std::string& line, float scale, float x,
                float baseline) const;
  std::vector<unsigned char> file_;
  Font* font_;
};

/// Splits `text` into lines of at most `max_chars` characters at spaces (a longer word stays
/// whole).
std::vector<std::string> wrapWords(const std::string& text, std::size_t max_chars);

}  // namespace pool::render
