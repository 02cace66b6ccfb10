// Small SVG writer for the plot: table metres to pixels, and elements with fixed-precision numbers.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

namespace pool::scenario {

/// Maps the table frame (metres, +y up the page) to SVG pixels (+y down).
struct SvgView {
  double scale = 400.0;          ///< px per metre
  Eigen::Vector2d origin{0, 0};  ///< pixel position of the table's centre
  double width = 0.0;            ///< px
  double height = 0.0;           ///< px

  Eigen::Vector2d toPx(const Eigen::Vector2d& table_xy) const {
    return {origin.x() + scale * table_xy.x(), origin.y() - scale * table_xy.y()};
  }
};

/// A pixel value with two decimals ("12.30"); never "-0.00".
std::string px(double value);

/// `<circle cx cy r ATTRS/>`, centre and radius in px.
std::string svgCircle(const Eigen::Vector2d& centre, double radius, std::string_view attrs);
/// `<line .../>` between two pixel points.
std::string svgLine(const Eigen::Vector2d& a, const Eigen::Vector2d& b, std::string_view attrs);
/// `<rect .../>` from its top-left corner and size in px.
std::string svgRect(const Eigen::Vector2d& top_left, const Eigen::Vector2d& size,
                    std::string_view attrs);
/// `<polyline points=... ATTRS/>`.
std::string svgPolyline(const std::vector<Eigen::Vector2d>& points, std::string_view attrs);
/// `<polygon points=... ATTRS/>`.
std::string svgPolygon(const std::vector<Eigen::Vector2d>& points, std::string_view attrs);
/// A rectangle centred on the table's centre with half-extents in metres.
std::string svgCentredRect(const SvgView& view, double half_x, double half_y,
                           std::string_view attrs);

}  // namespace pool::scenario
