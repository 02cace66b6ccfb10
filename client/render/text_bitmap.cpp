// Rasterises lines of text into coverage bitmaps with stb_truetype (implementation in libstb).
#include "client/render/text_bitmap.h"

#include <stb_truetype.h>

#include <algorithm>
#include <fstream>
#include <iterator>
#include <sstream>
#include <stdexcept>

namespace pool::render {

struct TextRasterizer::Font {
  stbtt_fontinfo info;
};

TextRasterizer::TextRasterizer(const std::string& font_path) : font_(new Font) {
  std::ifstream in(font_path, std::ios::binary);
  file_.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  if (file_.empty() || stbtt_InitFont(&font_->info, file_.data(), 0) == 0) {
    delete font_;
    throw std::runtime_error("cannot load the font " + font_path + " (install fonts-dejavu-core)");
  }
}

TextRasterizer::~TextRasterizer() {
  delete font_;
}

float TextRasterizer::lineWidth(const std::string& line, float scale) const {
  float width = 0.0f;
  for (std::size_t i = 0; i < line.size(); ++i) {
    int advance = 0, bearing = 0;
    stbtt_GetCodepointHMetrics(&font_->info, static_cast<unsigned char>(line[i]), &advance,
                               &bearing);
    width += static_cast<float>(advance) * scale;
    if (i + 1 < line.size()) {
      width += scale * static_cast<float>(stbtt_GetCodepointKernAdvance(
                           &font_->info, static_cast<unsigned char>(line[i]),
                           static_cast<unsigned char>(line[i + 1])));
    }
  }
  return width;
}

void TextRasterizer::drawLine(TextBitmap& bitmap, const std::string& line, float scale, float x,
                              float baseline) const {
  for (std::size_t i = 0; i < line.size(); ++i) {
    const int c = static_cast<unsigned char>(line[i]);
    int advance = 0, bearing = 0, x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    stbtt_GetCodepointHMetrics(&font_->info, c, &advance, &bearing);
    stbtt_GetCodepointBitmapBox(&font_->info, c, scale, scale, &x0, &y0, &x1, &y1);
    const int left = static_cast<int>(x) + x0;
    const int top = static_cast<int>(baseline) + y0;
    // Glyphs are drawn into a scratch buffer and max-blended, so overlapping glyphs keep their ink.
    std::vector<unsigned char> glyph(static_cast<std::size_t>(std::max(1, (x1 - x0) * (y1 - y0))));
    stbtt_MakeCodepointBitmap(&font_->info, glyph.data(), x1 - x0, y1 - y0, x1 - x0, scale, scale,
                              c);
    for (int gy = 0; gy < y1 - y0; ++gy) {
      for (int gx = 0; gx < x1 - x0; ++gx) {
        const int px = left + gx, py = top + gy;
        if (px < 0 || py < 0 || px >= bitmap.width || py >= bitmap.height) continue;
        auto& dst = bitmap.coverage[static_cast<std::size_t>(py * bitmap.width + px)];
        dst = std::max(dst, glyph[static_cast<std::size_t>(gy * (x1 - x0) + gx)]);
      }
    }
    x += static_cast<float>(advance) * scale;
    if (i + 1 < line.size()) {
      x += scale * static_cast<float>(stbtt_GetCodepointKernAdvance(
                       &font_->info, c, static_cast<unsigned char>(line[i + 1])));
    }
  }
}

TextBitmap TextRasterizer::draw(const std::vector<std::string>& lines, int width, int height,
                                float pixel_height) const {
  TextBitmap bitmap{width, height,
                    std::vector<std::uint8_t>(static_cast<std::size_t>(width * height), 0)};
  if (lines.empty()) return bitmap;
  float scale = stbtt_ScaleForPixelHeight(&font_->info, pixel_height);
  // Shrink until the widest line and the stack of lines fit the cell (5 % margin).
  float widest = 0.0f;
  for (const auto& line : lines) widest = std::max(widest, lineWidth(line, scale));
  float line_height = pixel_height;
  const float fit = std::min(
      0.95f * static_cast<float>(width) / std::max(widest, 1.0f),
      0.95f * static_cast<float>(height) / (line_height * static_cast<float>(lines.size())));
  if (fit < 1.0f) {
    scale *= fit;
    line_height *= fit;
  }
  int ascent = 0, descent = 0, gap = 0;
  stbtt_GetFontVMetrics(&font_->info, &ascent, &descent, &gap);
  const float cap = static_cast<float>(ascent + descent) * scale;  // descent is negative
  const float block = line_height * static_cast<float>(lines.size());
  float top = (static_cast<float>(height) - block) * 0.5f;
  for (const auto& line : lines) {
    const float x = (static_cast<float>(width) - lineWidth(line, scale)) * 0.5f;
    const float baseline = top + (line_height + cap) * 0.5f;
    drawLine(bitmap, line, scale, x, baseline);
    top += line_height;
  }
  return bitmap;
}

std::vector<std::string> wrapWords(const std::string& text, std::size_t max_chars) {
  std::vector<std::string> lines;
  std::istringstream words(text);
  std::string word, line;
  while (words >> word) {
    if (!line.empty() && line.size() + 1 + word.size() > max_chars) {
      lines.push_back(line);
      line.clear();
    }
    line += (line.empty() ? "" : " ") + word;
  }
  if (!line.empty()) lines.push_back(line);
  return lines;
}

}  // namespace pool::render
