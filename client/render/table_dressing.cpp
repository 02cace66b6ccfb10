// The table's wooden and leather parts around the collision mesh.
#include "client/render/table_dressing.h"

#include <algorithm>
#include <cmath>
#include <set>

#include "client/render/diamonds.h"
#include "client/render/hall_layout.h"

namespace pool::render {

namespace {

constexpr float kFine = 0.006f;   // grid step near the pockets, m
constexpr float kCoarse = 0.12f;  // grid step elsewhere, m
constexpr float kNear = 0.03f;    // fine steps this far beyond a pocket's cut, m
// Facets round a pocket: seen from 30 cm at 2560 × 1440 a cut of 6 cm radius spans about 390 px,
// and a facet strays under half a pixel from the circle (40 strayed 1.2 px).
constexpr int kPocketSlices = 64;
constexpr float kLegHalfTop = 0.065f, kLegHalfFoot = 0.045f;

void addTriangle(MeshData& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 na, glm::vec3 nb,
                 glm::vec3 nc) {
  mesh.positions.insert(mesh.positions.end(), {a, b, c});
  mesh.normals.insert(mesh.normals.end(), {na, nb, nc});
}

/// A quad with a normal per vertex (smooth across a curved surface).
void addSmoothQuad(MeshData& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d, glm::vec3 na,
                   glm::vec3 nb, glm::vec3 nc, glm::vec3 nd) {
  addTriangle(mesh, a, b, c, na, nb, nc);
  addTriangle(mesh, a, c, d, na, nc, nd);
}

struct Hole {
  glm::vec2 centre;
  float radius;
};

/// The rail band's extent: outside the cushions' backs, inside the table's outer edge.
struct Band {
  float inner_x, inner_y;  ///< the cushions' backs
  float outer_x, outer_y;  ///< the rails' outer faces
  bool contains(glm::vec2 p) const {
    const bool outside_inner = std::abs(p.x) > inner_x || std::abs(p.y) > inner_y;
    return outside_inner && std::abs(p.x) < outer_x && std::abs(p.y) < outer_y;
  }
};

/// Grid lines over [-outer, outer]: coarse, fine within reach of each pocket, and `exact` ones.
std::vector<float> gridLines(float outer, const std::vector<float>& pockets, float reach,
                             const std::vector<float>& exact) {
  std::set<float> lines(exact.begin(), exact.end());
  lines.insert(-outer);
  lines.insert(outer);
  for (float v = -outer; v < outer; v += kCoarse) lines.insert(v);
  for (const float c : pockets) {
    for (float v = c - reach; v <= c + reach; v += kFine) {
      if (std::abs(v) < outer) lines.insert(v);
    }
  }
  return {lines.begin(), lines.end()};
}

/// The flat rail top: the band minus the pockets' cuts, as runs of grid cells (one quad per run
/// along x in each row), fine near the pockets so the cut is round.
MeshData railTop(const Band& band, const std::vector<Hole>& holes, float inset, float z) {
  std::vector<float> hole_x, hole_y;
  float reach = 0.0f;
  for (const Hole& h : holes) {
    hole_x.push_back(h.centre.x);
    hole_y.push_back(h.centre.y);
    reach = std::max(reach, h.radius + kNear);
  }
  const float ox = band.outer_x - inset, oy = band.outer_y - inset;
  const auto xs = gridLines(ox, hole_x, reach, {-band.inner_x, band.inner_x});
  const auto ys = gridLines(oy, hole_y, reach, {-band.inner_y, band.inner_y});
  const auto keep = [&](glm::vec2 c) {
    if (!band.contains(c)) return false;
    return std::all_of(holes.begin(), holes.end(), [&](const Hole& h) {
      return glm::length(c - h.centre) > h.radius + 0.5f * kRimWidth;
    });
  };
  MeshData mesh;
  for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
    const float y0 = ys[j], y1 = ys[j + 1], cy = 0.5f * (y0 + y1);
    std::size_t i = 0;
    while (i + 1 < xs.size()) {
      if (!keep({0.5f * (xs[i] + xs[i + 1]), cy})) {
        ++i;
        continue;
      }
      const float x0 = xs[i];
      while (i + 1 < xs.size() && keep({0.5f * (xs[i] + xs[i + 1]), cy})) ++i;
      addQuad(mesh, {x0, y0, z}, {xs[i], y0, z}, {xs[i], y1, z}, {x0, y1, z});
    }
  }
  return mesh;
}

/// The quarter-round along the outer edge, mitred at the corners: from the rail top `round` in
/// from the edge down to the outer face `round` below the top.
MeshData railEdge(const Band& band, float top, float round) {
  MeshData mesh;
  constexpr int kSteps = 6;
  // Each side: its outward normal in the plane and its half-length along the side.
  const glm::vec2 outward[4] = {{0, -1}, {1, 0}, {0, 1}, {-1, 0}};
  for (const glm::vec2 out : outward) {
    const glm::vec2 along(-out.y, out.x);
    const float reach = std::abs(out.x) > 0 ? band.outer_x : band.outer_y;  // to this side's face
    const float half = std::abs(out.x) > 0 ? band.outer_y : band.outer_x;   // along the side
    for (int s = 0; s < kSteps; ++s) {
      const auto at = [&](int k, float sign) {
        const float phi = 1.5707963f * static_cast<float>(k) / kSteps;
        const float from_face = round * (1.0f - std::sin(phi));  // inside the outer face
        const float z = top - round + round * std::cos(phi);
        const glm::vec2 p = out * (reach - from_face) + along * (sign * (half - from_face));
        return glm::vec3(p, z);
      };
      const auto normal = [&](int k) {
        const float phi = 1.5707963f * static_cast<float>(k) / kSteps;
        return glm::vec3(out * std::sin(phi), std::cos(phi));
      };
      addSmoothQuad(mesh, at(s, -1.0f), at(s, 1.0f), at(s + 1, 1.0f), at(s + 1, -1.0f), normal(s),
                    normal(s), normal(s + 1), normal(s + 1));
    }
  }
  return mesh;
}

/// The apron's outer faces from under the quarter-round down to kApronBottom, its bottom edge,
/// and its inner faces.
MeshData apron(const Band& band, float from_z) {
  MeshData mesh;
  const float bottom = hall::kApronBottom, thick = 0.03f;
  const float x = band.outer_x, y = band.outer_y;
  for (const float inset : {0.0f, thick}) {
    const float ax = x - inset, ay = y - inset;
    const glm::vec2 c[4] = {{-ax, -ay}, {ax, -ay}, {ax, ay}, {-ax, ay}};
    for (int i = 0; i < 4; ++i) {
      const glm::vec2 a = c[i], b = c[(i + 1) % 4];
      addQuad(mesh, {a, bottom}, {b, bottom}, {b, from_z}, {a, from_z});
    }
  }
  const glm::vec2 o[4] = {{-x, -y}, {x, -y}, {x, y}, {-x, y}};
  const glm::vec2 in[4] = {{-x + thick, -y + thick},
                           {x - thick, -y + thick},
                           {x - thick, y - thick},
                           {-x + thick, y - thick}};
  for (int i = 0; i < 4; ++i) {
    const int j = (i + 1) % 4;
    addQuad(mesh, {o[i], bottom}, {in[i], bottom}, {in[j], bottom}, {o[j], bottom});
  }
  return mesh;
}

/// A tapered square leg from the floor to the apron's bottom, on a foot block.
MeshData leg(glm::vec2 at) {
  MeshData mesh;
  const float z0 = hall::kFloorZ + 0.05f, z1 = hall::kApronBottom;
  const glm::vec2 corner[4] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
  for (int i = 0; i < 4; ++i) {
    const glm::vec2 a = corner[i], b = corner[(i + 1) % 4];
    addQuad(mesh, {at + a * kLegHalfFoot, z0}, {at + b * kLegHalfFoot, z0},
            {at + b * kLegHalfTop, z1}, {at + a * kLegHalfTop, z1});
  }
  append(mesh, box({at - glm::vec2(0.07f), hall::kFloorZ}, {at + glm::vec2(0.07f), z0}));
  return mesh;
}

/// A pocket's liner: leather round the cut from the rail top down to the slate where the rail
/// stands (not across the pocket's mouth), then a cylinder under the slate and a cup. Normals
/// point inward, toward whoever looks in.
void liner(MeshData& mesh, const Hole& hole, const Band& band, float top) {
  const float depth = -kLinerDepth, cup = depth - 0.04f;
  for (int i = 0; i < kPocketSlices; ++i) {
    const float a0 = 6.2831853f * static_cast<float>(i) / kPocketSlices;
    const float a1 = 6.2831853f * static_cast<float>(i + 1) / kPocketSlices;
    const glm::vec2 d0(std::cos(a0), std::sin(a0)), d1(std::cos(a1), std::sin(a1));
    const glm::vec3 n0(-d0, 0.0f), n1(-d1, 0.0f);
    const glm::vec2 p0 = hole.centre + d0 * hole.radius, p1 = hole.centre + d1 * hole.radius;
    const glm::vec2 mid = hole.centre + glm::normalize(d0 + d1) * (hole.radius + kRimWidth);
    if (band.contains(mid)) {
      addSmoothQuad(mesh, {p0, 0.0f}, {p1, 0.0f}, {p1, top + kRailCapLift},
                    {p0, top + kRailCapLift}, n0, n1, n1, n0);
    }
    addSmoothQuad(mesh, {p0, depth}, {p1, depth}, {p1, 0.0f}, {p0, 0.0f}, n0, n1, n1, n0);
    // The cup: narrowing to half the radius, then closed.
    const glm::vec2 q0 = hole.centre + d0 * (0.5f * hole.radius);
    const glm::vec2 q1 = hole.centre + d1 * (0.5f * hole.radius);
    const glm::vec3 m0 = glm::normalize(glm::vec3(-d0, 1.0f)),
                    m1 = glm::normalize(glm::vec3(-d1, 1.0f));
    addSmoothQuad(mesh, {q0, cup}, {q1, cup}, {p1, depth}, {p0, depth}, m0, m1, n1, n0);
    const glm::vec3 up(0.0f, 0.0f, 1.0f);
    addTriangle(mesh, {hole.centre, cup}, {q0, cup}, {q1, cup}, up, up, up);
  }
}

/// The leather rim round a pocket's cut on the rail top, where the rail stands.
void rim(MeshData& mesh, const Hole& hole, const Band& band, float z) {
  for (int i = 0; i < kPocketSlices; ++i) {
    const float a0 = 6.2831853f * static_cast<float>(i) / kPocketSlices;
    const float a1 = 6.2831853f * static_cast<float>(i + 1) / kPocketSlices;
    const glm::vec2 d0(std::cos(a0), std::sin(a0)), d1(std::cos(a1), std::sin(a1));
    const glm::vec2 mid = hole.centre + glm::normalize(d0 + d1) * (hole.radius + kRimWidth);
    if (!band.contains(mid)) continue;
    const float r0 = hole.radius, r1 = hole.radius + kRimWidth;
    addQuad(mesh, {hole.centre + d0 * r0, z}, {hole.centre + d0 * r1, z},
            {hole.centre + d1 * r1, z}, {hole.centre + d1 * r0, z});
  }
}

}  // namespace

std::vector<NamedMesh> tableDressing(const pool::table::TableGeometry& geometry,
                                     float cushion_width) {
  const RailExtent rails = railExtent(geometry, cushion_width);
  const Band band{rails.half_length + rails.cushion_width, rails.half_width + rails.cushion_width,
                  rails.half_length + rails.cushion_width + rails.rail_width,
                  rails.half_width + rails.cushion_width + rails.rail_width};
  std::vector<Hole> holes;
  for (const auto& h : geometry.holes) {
    holes.push_back({{static_cast<float>(h.centre.x()), static_cast<float>(h.centre.y())},
                     static_cast<float>(h.radius)});
  }
  const float top = rails.top + kRailCapLift;
  const float round = std::min(kRailRound, 0.3f * rails.rail_width);
  std::vector<NamedMesh> parts;
  parts.push_back({"rail_top", railTop(band, holes, round, top)});
  parts.push_back({"rail_edge", railEdge(band, top, round)});
  parts.push_back({"apron", apron(band, top - round)});
  MeshData underside;
  addQuad(underside, {-band.outer_x, -band.outer_y, hall::kApronBottom + 0.01f},
          {-band.outer_x, band.outer_y, hall::kApronBottom + 0.01f},
          {band.outer_x, band.outer_y, hall::kApronBottom + 0.01f},
          {band.outer_x, -band.outer_y, hall::kApronBottom + 0.01f});
  parts.push_back({"underside", underside});
  MeshData legs;
  const float lx = band.outer_x - 0.16f, ly = band.outer_y - 0.14f;
  for (const float sx : {-1.0f, 1.0f}) {
    for (const float sy : {-1.0f, 1.0f}) append(legs, leg({sx * lx, sy * ly}));
  }
  if (geometry.length > 2.3) {  // a long table has a pair under its middle too
    for (const float sy : {-1.0f, 1.0f}) append(legs, leg({0.0f, sy * ly}));
  }
  parts.push_back({"leg", legs});
  MeshData liners, rims;
  for (const Hole& h : holes) {
    liner(liners, h, band, rails.top);
    rim(rims, h, band, top + kRailCapLift);
  }
  parts.push_back({"pocket_liner", liners});
  parts.push_back({"pocket_rim", rims});
  return parts;
}

}  // namespace pool::render
