// Writes table geometry as Wavefront OBJ and reads it back through assimp.
//
// Encoding: each mesh part is an object `o <part>` of `v` and `f` lines. Each nose segment is an
// object `o nose_<name>` with two `v` lines (a, then b, at the nose height) and one `l` line from a
// to b: the side a ball may be on is to the left of a → b seen from above, so the normal is the
// left perpendicular of (b − a). Each pocket hole is `o hole_<name>`, a closed `l` loop through
// the vertices of its polygonal circle at z = 0. Assimp's OBJ importer keeps `l` lines as line
// primitives (one two-index face per segment, in order), so no other encoding is needed. The two
// facings of a pocket share one object name; assimp merges them into one object with two segments.
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <assimp/Importer.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <numbers>

#include "table/table_geometry.h"
#include "table/table_layout.h"

namespace pool::table {
namespace {

using Vec2 = Eigen::Vector2d;
using Vec3 = Eigen::Vector3d;

/// Fixed-point number with 9 decimals; never "-0.000000000".
std::string number(double v) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.9f", v);
  std::string s = buf;
  if (s.find_first_not_of("-0.") == std::string::npos && s.starts_with('-')) s.erase(0, 1);
  return s;
}

/// Accumulates OBJ text; vertex indices are global and 1-based.
class ObjWriter {
 public:
  void comment(const std::string& text) { out_ += "# " + text + "\n"; }
  void object(const std::string& name) { out_ += "o " + name + "\n"; }

  /// Writes a vertex and returns its OBJ index.
  std::size_t vertex(const Vec3& p) {
    out_ += "v " + number(p.x()) + " " + number(p.y()) + " " + number(p.z()) + "\n";
    return ++count_;
  }

  void element(char kind, const std::vector<std::size_t>& indices) {
    out_ += kind;
    // Appended piece by piece: `" " + std::to_string(i)` trips g++ 12's -Wrestrict false
    // positive at -O3 (GCC bug 105651).
    for (std::size_t i : indices) {
      out_ += ' ';
      out_ += std::to_string(i);
    }
    out_ += '\n';
  }

  std::string take() { return std::move(out_); }

 private:
  std::string out_;
  std::size_t count_ = 0;
};

void writePart(ObjWriter& w, const MeshPart& part) {
  w.object(part.name);
  std::size_t first = 0;
  for (const Vec3& v : part.vertices) {
    const std::size_t index = w.vertex(v);
    if (first == 0) first = index;
  }
  for (const auto& t : part.triangles) w.element('f', {first + t[0], first + t[1], first + t[2]});
}

void writeNose(ObjWriter& w, const NoseSegment& nose, double z) {
  w.object("nose_" + nose.name);
  const std::size_t a = w.vertex({nose.a.x(), nose.a.y(), z});
  const std::size_t b = w.vertex({nose.b.x(), nose.b.y(), z});
  w.element('l', {a, b});
}

void writeHole(ObjWriter& w, const PocketHole& hole) {
  w.object("hole_" + hole.name);
  std::vector<std::size_t> loop;
  for (int i = 0; i < detail::kHoleSegments; ++i) {
    const double a = 2.0 * std::numbers::pi * i / detail::kHoleSegments;
    const Vec2 p = hole.centre + hole.radius * Vec2(std::cos(a), std::sin(a));
    loop.push_back(w.vertex({p.x(), p.y(), 0.0}));
  }
  loop.push_back(loop.front());
  w.element('l', loop);
}

// ---- reading back ----------------------------------------------------------------------------

Vec3 toVec(const aiVector3D& v) {
  return {static_cast<double>(v.x), static_cast<double>(v.y), static_cast<double>(v.z)};
}

/// Line faces (two indices) of a mesh, in order.
std::vector<std::pair<Vec3, Vec3>> lineSegments(const aiMesh& mesh) {
  std::vector<std::pair<Vec3, Vec3>> out;
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices == 2)
      out.emplace_back(toVec(mesh.mVertices[face.mIndices[0]]),
                       toVec(mesh.mVertices[face.mIndices[1]]));
  }
  return out;
}

/// Everything read from the file, before it becomes a TableGeometry.
struct Loaded {
  TableGeometry geometry;
  std::vector<double> nose_z;
  std::string error;
};

/// One nose per line segment: assimp merges objects of the same name (a pocket's two facings), in
/// file order.
void readNose(Loaded& out, const std::string& name, const aiMesh& mesh) {
  const auto segments = lineSegments(mesh);
  if (segments.empty()) {
    out.error = "nose_" + name + ": expected a line segment";
    return;
  }
  for (const auto& [a, b] : segments) {
    NoseSegment s;
    s.name = name;
    s.a = a.head<2>();
    s.b = b.head<2>();
    s.normal = detail::leftPerp(s.b - s.a).normalized();
    out.nose_z.push_back((a.z() + b.z()) / 2.0);
    out.geometry.noses.push_back(std::move(s));
  }
}

void readHole(Loaded& out, const std::string& name, const aiMesh& mesh) {
  const auto segments = lineSegments(mesh);
  if (segments.size() < 3) {
    out.error = "hole_" + name + ": expected a closed loop of lines";
    return;
  }
  Vec2 centre = Vec2::Zero();
  for (const auto& seg : segments)
    centre += seg.first.head<2>() / static_cast<double>(segments.size());
  double radius = 0.0;
  for (const auto& seg : segments)
    radius += (seg.first.head<2>() - centre).norm() / static_cast<double>(segments.size());
  out.geometry.holes.push_back(PocketHole{name, centre, radius});
}

void readPart(Loaded& out, const std::string& name, const aiMesh& mesh) {
  auto it = std::find_if(out.geometry.parts.begin(), out.geometry.parts.end(),
                         [&](const MeshPart& p) { return p.name == name; });
  if (it == out.geometry.parts.end()) {
    out.geometry.parts.push_back(MeshPart{name, {}, {}});
    it = std::prev(out.geometry.parts.end());
  }
  const auto base = static_cast<std::uint32_t>(it->vertices.size());
  for (unsigned v = 0; v < mesh.mNumVertices; ++v) it->vertices.push_back(toVec(mesh.mVertices[v]));
  for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
    const aiFace& face = mesh.mFaces[f];
    if (face.mNumIndices != 3) continue;
    it->triangles.push_back(
        {base + face.mIndices[0], base + face.mIndices[1], base + face.mIndices[2]});
  }
}

void readNode(Loaded& out, const aiScene& scene, const aiNode& node) {
  const std::string name = node.mName.C_Str();
  for (unsigned i = 0; i < node.mNumMeshes && out.error.empty(); ++i) {
    const aiMesh& mesh = *scene.mMeshes[node.mMeshes[i]];
    if (name.starts_with("nose_")) {
      readNose(out, name.substr(5), mesh);
    } else if (name.starts_with("hole_")) {
      readHole(out, name.substr(5), mesh);
    } else {
      readPart(out, name, mesh);
    }
  }
  for (unsigned i = 0; i < node.mNumChildren && out.error.empty(); ++i)
    readNode(out, scene, *node.mChildren[i]);
}

Result<TableGeometry> importMesh(const TableSpec& spec) {
  const std::string path = spec.collision_mesh.string();
  Assimp::Importer importer;
  const aiScene* scene =
      importer.ReadFile(path, aiProcess_Triangulate | aiProcess_JoinIdenticalVertices);
  if (scene == nullptr || scene->mRootNode == nullptr) {
    return Result<TableGeometry>::fail("collision_mesh: " + path + ": " +
                                       importer.GetErrorString());
  }
  Loaded loaded;
  readNode(loaded, *scene, *scene->mRootNode);
  if (!loaded.error.empty())
    return Result<TableGeometry>::fail("collision_mesh: " + path + ": " + loaded.error);
  if (loaded.geometry.noses.empty() || loaded.geometry.holes.empty() != !spec.pockets ||
      loaded.geometry.parts.empty()) {
    return Result<TableGeometry>::fail(
        "collision_mesh: " + path +
        (spec.pockets
             ? ": needs nose_*, hole_* and mesh objects"
             : ": needs nose_* and mesh objects, and no hole_* (a table without pockets)"));
  }
  TableGeometry& g = loaded.geometry;
  g.name = spec.name;
  g.length = spec.length;
  g.width = spec.width;
  g.nose_height = 0.0;
  for (double z : loaded.nose_z) g.nose_height += z / static_cast<double>(loaded.nose_z.size());
  g.trough_z = detail::kTroughHeadZ;
  return Result<TableGeometry>::ok(std::move(g));
}

}  // namespace

std::string toObj(const TableGeometry& geometry) {
  ObjWriter w;
  w.comment("table " + geometry.name +
            ": collision mesh written by pool-tablegen (metres, table frame, z up)");
  w.comment(
      "nose_*: l a b with the ball's side to the left of a->b; hole_*: closed loops at z = 0");
  for (const MeshPart& part : geometry.parts) writePart(w, part);
  for (const NoseSegment& nose : geometry.noses) writeNose(w, nose, geometry.nose_height);
  for (const PocketHole& hole : geometry.holes) writeHole(w, hole);
  return w.take();
}

Result<TableGeometry> loadTableGeometry(const TableSpec& spec) {
  if (spec.collision_mesh.empty())
    return Result<TableGeometry>::fail("collision_mesh: not set in the spec");
  try {
    return importMesh(spec);
  } catch (const std::exception& e) {
    return Result<TableGeometry>::fail("collision_mesh: " + spec.collision_mesh.string() + ": " +
                                       e.what());
  }
}

}  // namespace pool::table
