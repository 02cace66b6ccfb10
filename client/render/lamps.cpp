// Lamp placement and shade geometry.
#include "client/render/lamps.h"

namespace pool::render {

std::array<glm::vec3, 2> lampPositions(const pool::table::TableGeometry& geometry) {
  const float x = static_cast<float>(geometry.length) * 0.25f;
  return {glm::vec3(-x, 0.0f, kLampHeight), glm::vec3(x, 0.0f, kLampHeight)};
}

MeshData lampShade() {
  // The shade's rim is a little below the bulb so the bulb is hidden from the side.
  MeshData shade = openFrustum(0.16f, 0.05f, 0.13f, 40);
  for (auto& p : shade.positions) p.z -= 0.03f;
  MeshData rod = openFrustum(0.008f, 0.008f, 2.0f, 8);
  for (auto& p : rod.positions) p.z += 0.14f;
  append(shade, rod);
  return shade;
}

}  // namespace pool::render
