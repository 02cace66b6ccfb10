// Mesh builders on the CPU (flat-shaded table parts, UV spheres, discs, boxes, frustums): no GL,
// so the asset generators build with them too.
#include "client/render/mesh.h"

#include <cmath>
#include <numbers>

namespace pool::render {

namespace {

void addTriangle(MeshData& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 na, glm::vec3 nb,
                 glm::vec3 nc) {
  mesh.positions.insert(mesh.positions.end(), {a, b, c});
  mesh.normals.insert(mesh.normals.end(), {na, nb, nc});
}

glm::vec3 toVec(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}

glm::vec3 spherePoint(int stack, int slice, int stacks, int slices) {
  const double theta = std::numbers::pi * stack / stacks;
  const double phi = 2.0 * std::numbers::pi * slice / slices;
  return {static_cast<float>(std::sin(theta) * std::cos(phi)),
          static_cast<float>(std::sin(theta) * std::sin(phi)), static_cast<float>(std::cos(theta))};
}

}  // namespace

MeshData meshFromPart(const pool::table::MeshPart& part) {
  MeshData mesh;
  for (const auto& tri : part.triangles) {
    const glm::vec3 a = toVec(part.vertices[tri[0]]);
    const glm::vec3 b = toVec(part.vertices[tri[1]]);
    const glm::vec3 c = toVec(part.vertices[tri[2]]);
    const glm::vec3 cross = glm::cross(b - a, c - a);
    if (glm::length(cross) <= 0.0f) continue;
    const glm::vec3 n = glm::normalize(cross);
    addTriangle(mesh, a, b, c, n, n, n);
  }
  return mesh;
}

MeshData unitSphere(int stacks, int slices) {
  MeshData mesh;
  for (int i = 0; i < stacks; ++i) {
    for (int j = 0; j < slices; ++j) {
      const glm::vec3 p00 = spherePoint(i, j, stacks, slices);
      const glm::vec3 p01 = spherePoint(i, j + 1, stacks, slices);
      const glm::vec3 p10 = spherePoint(i + 1, j, stacks, slices);
      const glm::vec3 p11 = spherePoint(i + 1, j + 1, stacks, slices);
      addTriangle(mesh, p00, p10, p11, p00, p10, p11);
      addTriangle(mesh, p00, p11, p01, p00, p11, p01);
    }
  }
  return mesh;
}

MeshData unitDisc(int slices) {
  MeshData mesh;
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  for (int j = 0; j < slices; ++j) {
    const glm::vec3 a = spherePoint(1, j, 2, slices);
    const glm::vec3 b = spherePoint(1, j + 1, 2, slices);
    addTriangle(mesh, glm::vec3(0.0f), a, b, up, up, up);
  }
  return mesh;
}

MeshData box(glm::vec3 lo, glm::vec3 hi) {
  MeshData mesh;
  // Each face: its axis, its side, and two in-plane axes.
  for (int axis = 0; axis < 3; ++axis) {
    const int u = (axis + 1) % 3, v = (axis + 2) % 3;
    for (const float side : {-1.0f, 1.0f}) {
      glm::vec3 n(0.0f);
      n[axis] = side;
      auto corner = [&](bool hu, bool hv) {
        glm::vec3 p;
        p[axis] = side > 0.0f ? hi[axis] : lo[axis];
        p[u] = hu ? hi[u] : lo[u];
        p[v] = hv ? hi[v] : lo[v];
        return p;
      };
      addTriangle(mesh, corner(false, false), corner(true, false), corner(true, true), n, n, n);
      addTriangle(mesh, corner(false, false), corner(true, true), corner(false, true), n, n, n);
    }
  }
  return mesh;
}

MeshData openFrustum(float bottom, float top, float height, int slices) {
  MeshData mesh;
  const float slope = (bottom - top) / height;  // outward normal leans up as the side narrows
  for (int j = 0; j < slices; ++j) {
    const glm::vec3 a = spherePoint(1, j, 2, slices);
    const glm::vec3 b = spherePoint(1, j + 1, 2, slices);
    const glm::vec3 na = glm::normalize(glm::vec3(a.x, a.y, slope));
    const glm::vec3 nb = glm::normalize(glm::vec3(b.x, b.y, slope));
    const glm::vec3 a0 = a * bottom, b0 = b * bottom;
    const glm::vec3 a1 = a * top + glm::vec3(0, 0, height), b1 = b * top + glm::vec3(0, 0, height);
    addTriangle(mesh, a0, b0, b1, na, nb, nb);
    addTriangle(mesh, a0, b1, a1, na, nb, na);
  }
  return mesh;
}

void addQuad(MeshData& mesh, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
  const glm::vec3 cross = glm::cross(b - a, c - a);
  if (glm::length(cross) <= 0.0f) return;
  const glm::vec3 n = glm::normalize(cross);
  addTriangle(mesh, a, b, c, n, n, n);
  addTriangle(mesh, a, c, d, n, n, n);
}

MeshData transformed(const MeshData& mesh, const glm::mat4& model) {
  MeshData out;
  const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
  for (const glm::vec3& p : mesh.positions)
    out.positions.push_back(glm::vec3(model * glm::vec4(p, 1.0f)));
  for (const glm::vec3& n : mesh.normals) out.normals.push_back(glm::normalize(normal_matrix * n));
  return out;
}

void append(MeshData& mesh, const MeshData& more) {
  mesh.positions.insert(mesh.positions.end(), more.positions.begin(), more.positions.end());
  mesh.normals.insert(mesh.normals.end(), more.normals.begin(), more.normals.end());
}

}  // namespace pool::render
