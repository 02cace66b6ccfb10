// Where the rails, jaw facings and pocket holes of a spec lie, in the table frame.
#include "table/table_layout.h"

#include <cmath>
#include <numbers>

namespace pool::table::detail {
namespace {

using Vec2 = Eigen::Vector2d;

constexpr double kDegToRad = std::numbers::pi / 180.0;

/// Distance from a corner's meeting point to each jaw point, along the rail.
double cornerSetback(const TableSpec& spec) {
  return spec.corner.mouth / std::numbers::sqrt2;
}

PocketLayout cornerPocket(const TableSpec& spec, const char* name, double sx, double sy) {
  PocketLayout p;
  p.name = name;
  p.corner = true;
  p.reference = Vec2(sx * spec.length / 2.0, sy * spec.width / 2.0);
  p.outward = Vec2(sx, sy) / std::numbers::sqrt2;
  p.hole_centre = p.reference + spec.corner.hole_offset * p.outward;
  p.hole_radius = spec.corner.hole_radius;
  p.jaw_angle_deg = spec.corner.jaw_angle_deg;
  return p;
}

PocketLayout sidePocket(const TableSpec& spec, const char* name, double sy) {
  PocketLayout p;
  p.name = name;
  p.corner = false;
  p.reference = Vec2(0.0, sy * spec.width / 2.0);
  p.outward = Vec2(0.0, sy);
  p.hole_centre = p.reference + spec.side.hole_offset * p.outward;
  p.hole_radius = spec.side.hole_radius;
  p.jaw_angle_deg = spec.side.jaw_angle_deg;
  return p;
}

RailLayout rail(const char* name, Vec2 a, Vec2 b, int pocket_a, int pocket_b) {
  RailLayout r;
  r.name = name;
  r.a = a;
  r.b = b;
  r.normal = leftPerp(b - a).normalized();
  r.pocket_a = pocket_a;
  r.pocket_b = pocket_b;
  return r;
}

JawLayout jawAt(const TableSpec& spec, const RailLayout& r, int rail_index, bool at_a,
                const PocketLayout& pocket) {
  JawLayout j;
  j.pocket = at_a ? r.pocket_a : r.pocket_b;
  j.rail = rail_index;
  j.point = at_a ? r.a : r.b;
  j.along = (at_a ? (r.a - r.b) : (r.b - r.a)).normalized();
  j.outward = -r.normal;
  j.turn = (180.0 - pocket.jaw_angle_deg) * kDegToRad;
  j.facing = std::cos(j.turn) * j.along + std::sin(j.turn) * j.outward;
  j.end = j.point + j.facing * (spec.cushion_width / std::sin(j.turn));
  j.normal = std::sin(j.turn) * j.along - std::cos(j.turn) * j.outward;
  return j;
}

}  // namespace

std::vector<PocketLayout> pocketLayouts(const TableSpec& spec) {
  if (!spec.pockets) return {};
  return {cornerPocket(spec, "head_left_corner", -1.0, 1.0),
          sidePocket(spec, "left_side", 1.0),
          cornerPocket(spec, "foot_left_corner", 1.0, 1.0),
          cornerPocket(spec, "head_right_corner", -1.0, -1.0),
          sidePocket(spec, "right_side", -1.0),
          cornerPocket(spec, "foot_right_corner", 1.0, -1.0)};
}

std::vector<RailLayout> railLayouts(const TableSpec& spec) {
  const double hl = spec.length / 2.0;
  const double hw = spec.width / 2.0;
  if (!spec.pockets) {
    return {rail("head", {-hl, hw}, {-hl, -hw}, kNoPocket, kNoPocket),
            rail("foot", {hl, -hw}, {hl, hw}, kNoPocket, kNoPocket),
            rail("left", {hl, hw}, {-hl, hw}, kNoPocket, kNoPocket),
            rail("right", {-hl, -hw}, {hl, -hw}, kNoPocket, kNoPocket)};
  }
  const double s = cornerSetback(spec);
  const double ms = spec.side.mouth / 2.0;
  return {rail("head", {-hl, hw - s}, {-hl, -(hw - s)}, 0, 3),
          rail("foot", {hl, -(hw - s)}, {hl, hw - s}, 5, 2),
          rail("head_left", {-ms, hw}, {-hl + s, hw}, 1, 0),
          rail("foot_left", {hl - s, hw}, {ms, hw}, 2, 1),
          rail("head_right", {-hl + s, -hw}, {-ms, -hw}, 3, 4),
          rail("foot_right", {ms, -hw}, {hl - s, -hw}, 4, 5)};
}

std::vector<JawLayout> jawLayouts(const TableSpec& spec) {
  const std::vector<PocketLayout> pockets = pocketLayouts(spec);
  const std::vector<RailLayout> rails = railLayouts(spec);
  std::vector<JawLayout> jaws;
  for (int p = 0; p < static_cast<int>(pockets.size()); ++p) {
    for (int i = 0; i < static_cast<int>(rails.size()); ++i) {
      const RailLayout& r = rails[static_cast<std::size_t>(i)];
      if (r.pocket_a == p)
        jaws.push_back(jawAt(spec, r, i, true, pockets[static_cast<std::size_t>(p)]));
      if (r.pocket_b == p)
        jaws.push_back(jawAt(spec, r, i, false, pockets[static_cast<std::size_t>(p)]));
    }
  }
  return jaws;
}

Vec2 slateHalfExtent(const TableSpec& spec) {
  const double border = spec.cushion_width + spec.rail_width;
  return {spec.length / 2.0 + border, spec.width / 2.0 + border};
}

Tile holeTile(const TableSpec& spec, const PocketLayout& pocket) {
  const Vec2 outer = slateHalfExtent(spec);
  const double reach = pocket.hole_radius + kTileMargin;
  Tile t;
  for (int k = 0; k < 2; ++k) {
    const double c = pocket.hole_centre[k];
    const double dir = pocket.outward[k];
    if (dir > 0.0) {
      t.min[k] = c - reach;
      t.max[k] = outer[k];
    } else if (dir < 0.0) {
      t.min[k] = -outer[k];
      t.max[k] = c + reach;
    } else {
      t.min[k] = c - reach;
      t.max[k] = c + reach;
    }
  }
  return t;
}

}  // namespace pool::table::detail
