// Builds the table's triangle mesh: slate with holes, swept cushion profiles mitred into the jaws,
// pocket liners, wooden rails and the trough under the slate.
#include "table/table_mesh.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "table/table_layout.h"

namespace pool::table::detail {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

constexpr double kMinDoubleArea = 1e-14;  ///< |cross| below this: a degenerate triangle, skipped

Vec3 lift(const Vec2& p, double z) {
  return {p.x(), p.y(), z};
}
Vec3 horizontal(const Vec2& v) {
  return {v.x(), v.y(), 0.0};
}

/// Collects one part's triangles, sharing exactly equal vertices and orienting each triangle.
class PartBuilder {
 public:
  explicit PartBuilder(std::string name) { part_.name = std::move(name); }

  /// Adds a triangle whose normal points along `outward` (the side a ball may be on).
  void triangle(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& outward) {
    const Vec3 n = (b - a).cross(c - a);
    if (n.norm() < kMinDoubleArea) return;
    if (n.dot(outward) >= 0.0) {
      part_.triangles.push_back({index(a), index(b), index(c)});
    } else {
      part_.triangles.push_back({index(a), index(c), index(b)});
    }
  }

  /// Adds a convex planar polygon (vertices in order around it) as a fan.
  void polygon(const std::vector<Vec3>& ring, const Vec3& outward) {
    for (std::size_t i = 1; i + 1 < ring.size(); ++i)
      triangle(ring[0], ring[i], ring[i + 1], outward);
  }

  void quad(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d, const Vec3& outward) {
    polygon({a, b, c, d}, outward);
  }

  MeshPart take() { return std::move(part_); }

 private:
  std::uint32_t index(const Vec3& p) {
    const std::array<double, 3> key{p.x(), p.y(), p.z()};
    const auto [it, inserted] =
        index_.try_emplace(key, static_cast<std::uint32_t>(part_.vertices.size()));
    if (inserted) part_.vertices.push_back(p);
    return it->second;
  }

  MeshPart part_;
  std::map<std::array<double, 3>, std::uint32_t> index_;
};

// ---- cushion profile -------------------------------------------------------------------------

/// A point of the cushion's cross-section: `back` metres behind the nose line, `z` above the slate.
struct ProfilePoint {
  double back = 0.0;
  double z = 0.0;
};

/// Convex cross-section: the nose (innermost, at the nose height), the face under it sloping back
/// to the slate, the top a few mm above the nose, the back at cushion_width.
std::vector<ProfilePoint> cushionProfile(const TableSpec& spec) {
  const double h = spec.params.cushion_height;
  const double cw = spec.cushion_width;
  const double top = h + kCushionTopAboveNose;
  return {{0.5 * cw, 0.0}, {0.0, h}, {0.1 * cw, top}, {cw, top}, {cw, 0.0}};
}

/// Outward normal (back, z) of profile edge i → i+1.
ProfilePoint profileEdgeNormal(const std::vector<ProfilePoint>& profile, std::size_t i) {
  double cb = 0.0, cz = 0.0;
  for (const ProfilePoint& p : profile) {
    cb += p.back / static_cast<double>(profile.size());
    cz += p.z / static_cast<double>(profile.size());
  }
  const ProfilePoint& p = profile[i];
  const ProfilePoint& q = profile[(i + 1) % profile.size()];
  ProfilePoint n{q.z - p.z, -(q.back - p.back)};
  const double mid_b = (p.back + q.back) / 2.0 - cb;
  const double mid_z = (p.z + q.z) / 2.0 - cz;
  if (n.back * mid_b + n.z * mid_z < 0.0) n = {-n.back, -n.z};
  return n;
}

/// The section where a rail's sweep meets its jaw facing: the mitre of the two offset lines.
std::vector<Vec3> mitreSection(const JawLayout& jaw, const std::vector<ProfilePoint>& profile) {
  const Vec2 facing_back = -jaw.normal;
  const Vec2 mitre = (jaw.outward + facing_back) / (1.0 + std::cos(jaw.turn));
  std::vector<Vec3> out;
  for (const ProfilePoint& p : profile) out.push_back(lift(jaw.point + p.back * mitre, p.z));
  return out;
}

/// The section at the facing's far end, square to the facing.
std::vector<Vec3> facingEndSection(const JawLayout& jaw, const std::vector<ProfilePoint>& profile) {
  std::vector<Vec3> out;
  for (const ProfilePoint& p : profile) out.push_back(lift(jaw.end - p.back * jaw.normal, p.z));
  return out;
}

/// Side faces of the sweep between two sections; `back` is the horizontal direction behind the
/// nose.
void sweepFaces(PartBuilder& part, const std::vector<Vec3>& s0, const std::vector<Vec3>& s1,
                const std::vector<ProfilePoint>& profile, const Vec2& back) {
  for (std::size_t i = 0; i < profile.size(); ++i) {
    const std::size_t k = (i + 1) % profile.size();
    const ProfilePoint n = profileEdgeNormal(profile, i);
    const Vec3 outward = n.back * horizontal(back) + Vec3(0.0, 0.0, n.z);
    part.quad(s0[i], s0[k], s1[k], s1[i], outward);
  }
}

const JawLayout& jawOf(const std::vector<JawLayout>& jaws, int rail, const Vec2& point) {
  for (const JawLayout& j : jaws) {
    if (j.rail == rail && j.point == point) return j;
  }
  return jaws.front();  // unreachable: every rail end at a pocket has a jaw
}

/// The section where a rail's sweep ends: mitred into its jaw facing at a pocket, or at a corner
/// of a table without pockets mitred at 45° into the next cushion (both offset lines meet on the
/// corner's diagonal, `corner + back · (±1, ±1)`).
std::vector<Vec3> endSection(const RailLayout& rail, int index, bool at_a,
                             const std::vector<JawLayout>& jaws,
                             const std::vector<ProfilePoint>& profile) {
  const Vec2& point = at_a ? rail.a : rail.b;
  if ((at_a ? rail.pocket_a : rail.pocket_b) != kNoPocket)
    return mitreSection(jawOf(jaws, index, point), profile);
  const Vec2 diagonal(point.x() > 0.0 ? 1.0 : -1.0, point.y() > 0.0 ? 1.0 : -1.0);
  std::vector<Vec3> out;
  for (const ProfilePoint& p : profile) out.push_back(lift(point + p.back * diagonal, p.z));
  return out;
}

MeshPart cushionPart(const TableSpec& spec, const RailLayout& rail, int index,
                     const std::vector<JawLayout>& jaws) {
  const auto profile = cushionProfile(spec);
  PartBuilder part("cushion_" + rail.name);
  sweepFaces(part, endSection(rail, index, true, jaws, profile),
             endSection(rail, index, false, jaws, profile), profile, -rail.normal);
  return part.take();
}

MeshPart jawPart(const TableSpec& spec, const PocketLayout& pocket, int index,
                 const std::vector<JawLayout>& jaws) {
  const auto profile = cushionProfile(spec);
  PartBuilder part("jaw_" + pocket.name);
  for (const JawLayout& j : jaws) {
    if (j.pocket != index) continue;
    const auto end = facingEndSection(j, profile);
    sweepFaces(part, mitreSection(j, profile), end, profile, -j.normal);
    part.polygon(end, horizontal(j.facing));
  }
  return part.take();
}

// ---- slate -----------------------------------------------------------------------------------

std::vector<Vec2> holeCircle(const PocketLayout& pocket) {
  std::vector<Vec2> pts;
  for (int i = 0; i < kHoleSegments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / kHoleSegments;
    pts.push_back(pocket.hole_centre + pocket.hole_radius * Vec2(std::cos(a), std::sin(a)));
  }
  return pts;
}

double angleOf(const Vec2& v) {
  const double a = std::atan2(v.y(), v.x());
  return a < 0.0 ? a + 2.0 * std::numbers::pi : a;
}

/// Where the ray from `from` along `dir` leaves the tile.
Vec2 rayToTileEdge(const Tile& tile, const Vec2& from, const Vec2& dir) {
  double t = std::numeric_limits<double>::infinity();
  for (int k = 0; k < 2; ++k) {
    if (dir[k] > 0.0) t = std::min(t, (tile.max[k] - from[k]) / dir[k]);
    if (dir[k] < 0.0) t = std::min(t, (tile.min[k] - from[k]) / dir[k]);
  }
  return from + t * dir;
}

/// The ring between the hole's circle and its tile: one convex fan per circle segment.
void holeRing(PartBuilder& part, const Tile& tile, const PocketLayout& pocket) {
  const auto circle = holeCircle(pocket);
  const std::array<Vec2, 4> corners{
      Vec2(tile.min.x(), tile.min.y()), Vec2(tile.max.x(), tile.min.y()),
      Vec2(tile.max.x(), tile.max.y()), Vec2(tile.min.x(), tile.max.y())};
  const Vec3 up(0.0, 0.0, 1.0);
  constexpr double kAngleEps = 1e-12;
  for (int i = 0; i < kHoleSegments; ++i) {
    const int k = (i + 1) % kHoleSegments;
    const double a0 = 2.0 * std::numbers::pi * i / kHoleSegments;
    const double a1 = 2.0 * std::numbers::pi * (i + 1) / kHoleSegments;
    const Vec2& p0 = circle[static_cast<std::size_t>(i)];
    const Vec2& p1 = circle[static_cast<std::size_t>(k)];
    std::vector<Vec3> ring{
        lift(p0, 0.0),
        lift(rayToTileEdge(tile, pocket.hole_centre, (p0 - pocket.hole_centre).normalized()), 0.0)};
    for (const Vec2& c : corners) {
      const double a = angleOf(c - pocket.hole_centre);
      if (a > a0 + kAngleEps && a < a1 - kAngleEps) ring.push_back(lift(c, 0.0));
    }
    ring.push_back(
        lift(rayToTileEdge(tile, pocket.hole_centre, (p1 - pocket.hole_centre).normalized()), 0.0));
    ring.push_back(lift(p1, 0.0));
    part.polygon(ring, up);
  }
}

std::vector<double> sortedUnique(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  v.erase(std::unique(v.begin(), v.end()), v.end());
  return v;
}

/// Plain quads on the grid of tile edges, wherever no hole tile lies.
void slateGrid(PartBuilder& part, const TableSpec& spec, const std::vector<Tile>& tiles) {
  const Vec2 outer = slateHalfExtent(spec);
  std::vector<double> xs{-outer.x(), outer.x()}, ys{-outer.y(), outer.y()};
  for (const Tile& t : tiles) {
    xs.insert(xs.end(), {t.min.x(), t.max.x()});
    ys.insert(ys.end(), {t.min.y(), t.max.y()});
  }
  xs = sortedUnique(xs);
  ys = sortedUnique(ys);
  for (std::size_t i = 0; i + 1 < xs.size(); ++i) {
    for (std::size_t k = 0; k + 1 < ys.size(); ++k) {
      const Vec2 mid((xs[i] + xs[i + 1]) / 2.0, (ys[k] + ys[k + 1]) / 2.0);
      const bool in_tile = std::any_of(tiles.begin(), tiles.end(), [&](const Tile& t) {
        return mid.x() > t.min.x() && mid.x() < t.max.x() && mid.y() > t.min.y() &&
               mid.y() < t.max.y();
      });
      if (in_tile) continue;
      part.quad({xs[i], ys[k], 0.0}, {xs[i + 1], ys[k], 0.0}, {xs[i + 1], ys[k + 1], 0.0},
                {xs[i], ys[k + 1], 0.0}, {0.0, 0.0, 1.0});
    }
  }
}

MeshPart slatePart(const TableSpec& spec, const std::vector<PocketLayout>& pockets) {
  PartBuilder part("slate");
  std::vector<Tile> tiles;
  for (const PocketLayout& p : pockets) tiles.push_back(holeTile(spec, p));
  slateGrid(part, spec, tiles);
  for (std::size_t i = 0; i < pockets.size(); ++i) holeRing(part, tiles[i], pockets[i]);
  return part.take();
}

// ---- pockets, rails, trough ------------------------------------------------------------------

/// The hole's wall: a cylinder from the slate top to under the slate, facing its axis.
MeshPart pocketPart(const TableSpec& spec, const PocketLayout& pocket) {
  PartBuilder part("pocket_" + pocket.name);
  const auto circle = holeCircle(pocket);
  const double bottom = -(spec.slate_thickness + kLinerBelowSlate);
  for (std::size_t i = 0; i < circle.size(); ++i) {
    const Vec2& p0 = circle[i];
    const Vec2& p1 = circle[(i + 1) % circle.size()];
    const Vec3 inward = horizontal(pocket.hole_centre - (p0 + p1) / 2.0);
    part.quad(lift(p0, 0.0), lift(p1, 0.0), lift(p1, bottom), lift(p0, bottom), inward);
  }
  return part.take();
}

/// A closed convex box from its eight corners (bottom ring then top ring), faces pointing out.
void convexBox(PartBuilder& part, const std::array<Vec3, 8>& c) {
  Vec3 centre = Vec3::Zero();
  for (const Vec3& p : c) centre += p / 8.0;
  const std::array<std::array<int, 4>, 6> faces{
      {{0, 1, 2, 3}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}}};
  for (const auto& f : faces) {
    const auto at = [&](int k) {
      return c[static_cast<std::size_t>(f[static_cast<std::size_t>(k)])];
    };
    const Vec3 mid = (at(0) + at(1) + at(2) + at(3)) / 4.0;
    part.quad(at(0), at(1), at(2), at(3), mid - centre);
  }
}

/// The wooden rail behind a cushion, between the cushion's back mitre points.
MeshPart railPart(const TableSpec& spec, const RailLayout& rail, int index,
                  const std::vector<JawLayout>& jaws) {
  const auto profile = cushionProfile(spec);
  const double top = spec.params.cushion_height + kCushionTopAboveNose;
  const Vec2 out = -rail.normal * spec.rail_width;
  const Vec3 a3 = endSection(rail, index, true, jaws, profile)[3];
  const Vec3 b3 = endSection(rail, index, false, jaws, profile)[3];
  Vec2 a(a3.x(), a3.y()), b(b3.x(), b3.y());
  if (rail.pocket_a == kNoPocket && std::abs(rail.normal.x()) > 0.5) {
    // Without pockets the end rails reach over the corners, so the wood closes round the table.
    const Vec2 along = (b - a).normalized() * spec.rail_width;
    a -= along;
    b += along;
  }
  PartBuilder part("rail_" + rail.name);
  convexBox(part, {lift(a, 0.0), lift(b, 0.0), lift(b + out, 0.0), lift(a + out, 0.0), lift(a, top),
                   lift(b, top), lift(b + out, top), lift(a + out, top)});
  return part.take();
}

/// An open box under the whole slate, its floor sloping down toward the foot; faces point inside.
MeshPart troughPart(const TableSpec& spec) {
  const Vec2 e = slateHalfExtent(spec);
  const double head_z = troughHeadZ();
  const double foot_z = head_z - kTroughSlope * 2.0 * e.x();
  const double top = -spec.slate_thickness;
  const Vec3 h0(-e.x(), -e.y(), head_z), h1(-e.x(), e.y(), head_z), f0(e.x(), -e.y(), foot_z),
      f1(e.x(), e.y(), foot_z);
  const auto up = [top](const Vec3& p) { return Vec3(p.x(), p.y(), top); };
  PartBuilder part("trough");
  part.quad(h0, f0, f1, h1, {kTroughSlope, 0.0, 1.0});
  part.quad(h0, h1, up(h1), up(h0), {1.0, 0.0, 0.0});
  part.quad(f0, f1, up(f1), up(f0), {-1.0, 0.0, 0.0});
  part.quad(h0, f0, up(f0), up(h0), {0.0, 1.0, 0.0});
  part.quad(h1, f1, up(f1), up(h1), {0.0, -1.0, 0.0});
  return part.take();
}

}  // namespace

double troughHeadZ() {
  return kTroughHeadZ;
}

std::vector<MeshPart> buildMeshParts(const TableSpec& spec) {
  const auto pockets = pocketLayouts(spec);
  const auto rails = railLayouts(spec);
  const auto jaws = jawLayouts(spec);
  std::vector<MeshPart> parts{slatePart(spec, pockets)};
  for (int i = 0; i < static_cast<int>(rails.size()); ++i) {
    parts.push_back(cushionPart(spec, rails[static_cast<std::size_t>(i)], i, jaws));
  }
  for (int i = 0; i < static_cast<int>(pockets.size()); ++i) {
    parts.push_back(jawPart(spec, pockets[static_cast<std::size_t>(i)], i, jaws));
  }
  for (const PocketLayout& p : pockets) parts.push_back(pocketPart(spec, p));
  for (int i = 0; i < static_cast<int>(rails.size()); ++i) {
    parts.push_back(railPart(spec, rails[static_cast<std::size_t>(i)], i, jaws));
  }
  parts.push_back(troughPart(spec));
  return parts;
}

}  // namespace pool::table::detail
