// Writes named meshes as OBJ text with shared vertex and normal lines.
#include "client/render/obj_text.h"

#include <cstdio>
#include <map>

namespace pool::render {

namespace {

/// Index (1-based) of `line` among `lines`, added at the end when new.
std::size_t indexOf(std::map<std::string, std::size_t>& index, std::string& out,
                    const std::string& line) {
  const auto [it, added] = index.emplace(line, index.size() + 1);
  if (added) out += line;
  return it->second;
}

std::string formatted(const char* format, glm::vec3 v) {
  char text[96];
  // Negative zero prints as "-0.000000"; adding 0.0 makes it plain zero, so mirrored parts
  // write the same text on every platform.
  std::snprintf(text, sizeof text, format, double(v.x) + 0.0, double(v.y) + 0.0, double(v.z) + 0.0);
  return text;
}

}  // namespace

std::string objText(const std::vector<NamedMesh>& parts, const std::vector<std::string>& comment) {
  std::string out;
  for (const std::string& line : comment) out += "# " + line + "\n";
  std::map<std::string, std::size_t> positions;
  std::map<std::string, std::size_t> normals;
  for (const NamedMesh& part : parts) {
    out += "o " + part.name + "\n";
    std::string faces;
    const auto& mesh = part.mesh;
    for (std::size_t i = 0; i + 2 < mesh.positions.size(); i += 3) {
      faces += "f";
      for (std::size_t k = i; k < i + 3; ++k) {
        const std::size_t v =
            indexOf(positions, out, formatted("v %.6f %.6f %.6f\n", mesh.positions[k]));
        const std::size_t n =
            indexOf(normals, out, formatted("vn %.4f %.4f %.4f\n", mesh.normals[k]));
        faces += " " + std::to_string(v) + "//" + std::to_string(n);
      }
      faces += "\n";
    }
    out += faces;
  }
  return out;
}

}  // namespace pool::render
