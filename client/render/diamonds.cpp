// Diamond positions from the rails' extent, and the inlay's shape.
#include "client/render/diamonds.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace pool::render {

RailExtent railExtent(const pool::table::TableGeometry& geometry, float cushion_width) {
  RailExtent out;
  out.half_length = static_cast<float>(geometry.length) * 0.5f;
  out.half_width = static_cast<float>(geometry.width) * 0.5f;
  out.cushion_width = cushion_width;
  float outer_y = 0.0f;
  for (const auto& part : geometry.parts) {
    if (part.name.rfind("rail_", 0) != 0) continue;
    for (const auto& v : part.vertices) {
      out.top = std::max(out.top, static_cast<float>(v.z()));
      outer_y = std::max(outer_y, static_cast<float>(std::abs(v.y())));
    }
  }
  out.rail_width = std::max(0.0f, outer_y - out.half_width - cushion_width);
  return out;
}

std::vector<glm::vec3> diamondPositions(const RailExtent& r) {
  std::vector<glm::vec3> out;
  const float middle = r.cushion_width + r.rail_width * 0.5f;  // from the nose line
  for (const float side : {-1.0f, 1.0f}) {
    for (const int k : {1, 2, 3, 5, 6, 7}) {  // eighths of the length; 0, 4, 8 are pockets
      const float x = -r.half_length + 2.0f * r.half_length * static_cast<float>(k) / 8.0f;
      out.emplace_back(x, side * (r.half_width + middle), r.top);
    }
  }
  for (const float end : {-1.0f, 1.0f}) {
    for (const int k : {1, 2, 3}) {  // quarters of the width
      const float y = -r.half_width + 2.0f * r.half_width * static_cast<float>(k) / 4.0f;
      out.emplace_back(end * (r.half_length + middle), y, r.top);
    }
  }
  return out;
}

MeshData diamondInlay() {
  MeshData mesh;
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  const glm::vec3 c(0.0f), e(kDiamondHalfLong, 0.0f, 0.0f), n(0.0f, kDiamondHalfShort, 0.0f);
  const glm::vec3 w = -e, s = -n;
  mesh.positions = {c, e, n, c, n, w, c, w, s, c, s, e};
  mesh.normals.assign(mesh.positions.size(), up);
  return mesh;
}

}  // namespace pool::render
