// SVG elements for the plot, fixed-precision numbers so the file is byte-identical per outcome.
#include "scenario/svg_canvas.h"

#include <array>
#include <cstdio>

namespace pool::scenario {

std::string px(double value) {
  std::array<char, 32> buf{};
  std::snprintf(buf.data(), buf.size(), "%.2f", value);
  std::string text(buf.data());
  return text == "-0.00" ? "0.00" : text;
}

std::string svgCircle(const Eigen::Vector2d& centre, double radius, std::string_view attrs) {
  return "<circle cx=\"" + px(centre.x()) + "\" cy=\"" + px(centre.y()) + "\" r=\"" + px(radius) +
         "\" " + std::string(attrs) + "/>\n";
}

std::string svgLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b, std::string_view attrs) {
  return "<line x1=\"" + px(a.x()) + "\" y1=\"" + px(a.y()) + "\" x2=\"" + px(b.x()) + "\" y2=\"" +
         px(b.y()) + "\" " + std::string(attrs) + "/>\n";
}

namespace {

/// Appends " x,y" (no space before the first point). Piece by piece: `"" + std::string` trips
/// g++ 12's -Wrestrict false positive at -O3 (GCC bug 105651).
void appendPoint(std::string& list, const Eigen::Vector2d& p) {
  if (!list.empty()) list += ' ';
  list += px(p.x());
  list += ',';
  list += px(p.y());
}

}  // namespace

std::string svgRect(const Eigen::Vector2d& top_left, const Eigen::Vector2d& size,
                    std::string_view attrs) {
  return "<rect x=\"" + px(top_left.x()) + "\" y=\"" + px(top_left.y()) + "\" width=\"" +
         px(size.x()) + "\" height=\"" + px(size.y()) + "\" " + std::string(attrs) + "/>\n";
}

std::string svgPolyline(const std::vector<Eigen::Vector2d>& points, std::string_view attrs) {
  std::string list;
  for (const auto& p : points) appendPoint(list, p);
  return "<polyline points=\"" + list + "\" " + std::string(attrs) + "/>\n";
}

std::string svgPolygon(const std::vector<Eigen::Vector2d>& points, std::string_view attrs) {
  std::string list;
  for (const auto& p : points) appendPoint(list, p);
  return "<polygon points=\"" + list + "\" " + std::string(attrs) + "/>\n";
}

std::string svgCentredRect(const SvgView& view, double half_x, double half_y,
                           std::string_view attrs) {
  const Eigen::Vector2d top_left = view.toPx({-half_x, half_y});
  return svgRect(top_left, {2 * half_x * view.scale, 2 * half_y * view.scale}, attrs);
}

}  // namespace pool::scenario
