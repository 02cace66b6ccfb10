// Draws the table from above: rails, cushions, cloth, pocket holes, noses, diamonds, spots.
#include "scenario/plot_table.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <vector>

#include "table/rack.h"

namespace pool::scenario {
namespace {

// Diamonds sit on the rail's middle line: 3 between pockets on the long rails, 3 on each short
// rail.
std::string drawDiamonds(const SvgView& view, const table::TableSpec& spec,
                         const table::TableGeometry& g) {
  const double out = spec.cushion_width + 0.5 * spec.rail_width;
  const double hx = 0.5 * g.length + out;
  const double hy = 0.5 * g.width + out;
  const double r = 0.006 * view.scale;
  const std::string attrs = "class=\"diamond\" fill=\"#f3ead2\"";
  std::string s;
  for (int k = -3; k <= 3; ++k) {
    if (k == 0) continue;  // the side pockets
    const double x = k * g.length / 8.0;
    s += svgCircle(view.toPx({x, hy}), r, attrs) + svgCircle(view.toPx({x, -hy}), r, attrs);
  }
  for (int k = -1; k <= 1; ++k) {
    const double y = k * g.width / 4.0;
    s += svgCircle(view.toPx({hx, y}), r, attrs) + svgCircle(view.toPx({-hx, y}), r, attrs);
  }
  return s;
}

// Head string (dashed) and the head and foot spots.
std::string drawMarks(const SvgView& view, const table::TableSpec& spec,
                      const table::TableGeometry& g) {
  const table::Spots spots = table::spotsFor(spec);
  const double hy = 0.5 * g.width;
  std::string s = svgLine(
      view.toPx({spots.head_string_x, -hy}), view.toPx({spots.head_string_x, hy}),
      "class=\"head-string\" stroke=\"#9fd1b0\" stroke-width=\"1\" stroke-dasharray=\"4 4\"");
  const std::string dot = "class=\"spot\" fill=\"#d8efe0\"";
  s += svgCircle(view.toPx(spots.head_spot), 2.5, dot) +
       svgCircle(view.toPx(spots.foot_spot), 2.5, dot);
  return s;
}

// The cloth between a pocket's two jaws, so the cushion band opens at each pocket.
std::string drawThroats(const SvgView& view, const table::TableGeometry& g) {
  std::map<std::string, std::vector<Eigen::Vector2d>> jaws;  // by name: both facings' end points
  for (const auto& nose : g.noses) {
    if (nose.name.rfind("jaw_", 0) != 0) continue;
    jaws[nose.name].push_back(nose.a);
    jaws[nose.name].push_back(nose.b);
  }
  std::string s;
  for (auto& [name, pts] : jaws) {
    // The four ends make a convex outline once ordered by angle around their centre.
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto& p : pts) centre += p / static_cast<double>(pts.size());
    std::sort(pts.begin(), pts.end(), [&centre](const auto& a, const auto& b) {
      return std::atan2(a.y() - centre.y(), a.x() - centre.x()) <
             std::atan2(b.y() - centre.y(), b.x() - centre.x());
    });
    std::vector<Eigen::Vector2d> outline;
    for (const auto& p : pts) outline.push_back(view.toPx(p));
    s += svgPolygon(outline, "class=\"throat\" fill=\"#23834d\"");
  }
  return s;
}

std::string drawPockets(const SvgView& view, const table::TableGeometry& g) {
  std::string s;
  for (const auto& hole : g.holes) {
    s += svgCircle(view.toPx(hole.centre), hole.radius * view.scale,
                   "class=\"pocket\" data-name=\"" + hole.name + "\" fill=\"#0b0b0b\"");
  }
  return s;
}

std::string drawNoses(const SvgView& view, const table::TableGeometry& g) {
  std::string s;
  for (const auto& nose : g.noses) {
    s += svgLine(
        view.toPx(nose.a), view.toPx(nose.b),
        "class=\"nose\" data-name=\"" + nose.name + "\" stroke=\"#c9ecd4\" stroke-width=\"1.5\"");
  }
  return s;
}

}  // namespace

Eigen::Vector2d tableOuterHalfSize(const table::TableSpec& spec,
                                   const table::TableGeometry& geometry) {
  const double out = spec.cushion_width + spec.rail_width;
  return {0.5 * geometry.length + out, 0.5 * geometry.width + out};
}

std::string drawTable(const SvgView& view, const table::TableSpec& spec,
                      const table::TableGeometry& g) {
  const Eigen::Vector2d outer = tableOuterHalfSize(spec, g);
  const std::string corner = px(0.3 * spec.rail_width * view.scale);
  std::string s = svgCentredRect(view, outer.x(), outer.y(),
                                 "class=\"rail\" rx=\"" + corner +
                                     "\" fill=\"#7b4a22\" stroke=\"#4a2a10\" stroke-width=\"2\"");
  s += svgCentredRect(view, 0.5 * g.length + spec.cushion_width, 0.5 * g.width + spec.cushion_width,
                      "class=\"cushion\" fill=\"#17663c\"");
  s += svgCentredRect(view, 0.5 * g.length, 0.5 * g.width, "class=\"cloth\" fill=\"#23834d\"");
  s += drawThroats(view, g);
  s += drawMarks(view, spec, g);
  s += drawPockets(view, g);
  s += drawNoses(view, g);
  return s + drawDiamonds(view, spec, g);
}

}  // namespace pool::scenario
