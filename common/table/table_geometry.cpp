// Builds a table's collision geometry from its spec: nose lines, pocket holes and mesh parts.
#include "table/table_geometry.h"

#include "table/table_layout.h"
#include "table/table_mesh.h"

namespace pool::table {
namespace {

/// A segment from p to q, ordered so that its normal is the left perpendicular of (b − a).
NoseSegment orientedSegment(std::string name, const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                            const Eigen::Vector2d& normal) {
  NoseSegment s;
  s.name = std::move(name);
  const bool forward = detail::leftPerp(q - p).dot(normal) > 0.0;
  s.a = forward ? p : q;
  s.b = forward ? q : p;
  s.normal = detail::leftPerp(s.b - s.a).normalized();
  return s;
}

std::vector<NoseSegment> buildNoses(const TableSpec& spec) {
  std::vector<NoseSegment> noses;
  for (const detail::RailLayout& r : detail::railLayouts(spec)) {
    noses.push_back(orientedSegment(r.name, r.a, r.b, r.normal));
  }
  const auto pockets = detail::pocketLayouts(spec);
  for (const detail::JawLayout& j : detail::jawLayouts(spec)) {
    const std::string& pocket = pockets[static_cast<std::size_t>(j.pocket)].name;
    noses.push_back(orientedSegment("jaw_" + pocket, j.point, j.end, j.normal));
  }
  return noses;
}

std::vector<PocketHole> buildHoles(const TableSpec& spec) {
  std::vector<PocketHole> holes;
  for (const detail::PocketLayout& p : detail::pocketLayouts(spec)) {
    holes.push_back(PocketHole{p.name, p.hole_centre, p.hole_radius});
  }
  return holes;
}

}  // namespace

TableGeometry buildTableGeometry(const TableSpec& spec) {
  TableGeometry g;
  g.name = spec.name;
  g.length = spec.length;
  g.width = spec.width;
  g.nose_height = spec.params.cushion_height;
  g.noses = buildNoses(spec);
  g.holes = buildHoles(spec);
  g.parts = detail::buildMeshParts(spec);
  g.trough_z = detail::troughHeadZ();
  return g;
}

}  // namespace pool::table
