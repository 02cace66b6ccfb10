// The hall's pieces built from boxes, cylinders and quads.
#include "client/render/hall_room.h"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <map>
#include <string>

#include "client/render/hall_layout.h"

namespace pool::render {

namespace {

using namespace hall;

constexpr glm::vec3 kUp(0.0f, 0.0f, 1.0f);

/// Parts by name, in the order they are first used.
class Parts {
 public:
  MeshData& operator[](const std::string& name) {
    const auto it = index_.find(name);
    if (it != index_.end()) return parts_[it->second].mesh;
    index_.emplace(name, parts_.size());
    parts_.push_back({name, {}});
    return parts_.back().mesh;
  }
  std::vector<NamedMesh> take() { return std::move(parts_); }

 private:
  std::map<std::string, std::size_t> index_;
  std::vector<NamedMesh> parts_;
};

/// A vertical cylinder of `radius` from z0 to z1 around (x, y), closed at its top.
MeshData post(glm::vec2 at, float radius, float z0, float z1, int slices) {
  MeshData mesh = openFrustum(radius, radius, z1 - z0, slices);
  MeshData top = unitDisc(slices);
  for (auto& p : top.positions) p = p * radius + glm::vec3(0.0f, 0.0f, z1 - z0);
  append(mesh, top);
  return transformed(mesh, glm::translate(glm::mat4(1.0f), glm::vec3(at, z0)));
}

/// The frame of a wall piece: x along the wall, y out from the wall into the room, z up; the
/// origin at the piece's centre on the wall's face.
glm::mat4 wallFrame(const WallPiece& piece) {
  const glm::vec3 along = glm::cross(piece.inward, kUp);
  glm::mat4 m(1.0f);
  m[0] = glm::vec4(along, 0.0f);
  m[1] = glm::vec4(piece.inward, 0.0f);
  m[2] = glm::vec4(kUp, 0.0f);
  m[3] = glm::vec4(piece.centre, 1.0f);
  return m;
}

/// The four walls: oak panelling to kWainscotTop with a moulding on top and a skirting board,
/// wallpaper above. Faces point into the room.
void walls(Parts& parts) {
  const glm::vec3 corners[4] = {{-kHalfX, -kHalfY, 0.0f},
                                {kHalfX, -kHalfY, 0.0f},
                                {kHalfX, kHalfY, 0.0f},
                                {-kHalfX, kHalfY, 0.0f}};
  for (int i = 0; i < 4; ++i) {
    const glm::vec3 a = corners[i], b = corners[(i + 1) % 4];
    const auto at = [](glm::vec3 p, float z) { return glm::vec3(p.x, p.y, z); };
    // Counter-clockwise seen from inside the room: b, a going up.
    addQuad(parts["wainscot"], at(b, kFloorZ), at(a, kFloorZ), at(a, kWainscotTop),
            at(b, kWainscotTop));
    addQuad(parts["wallpaper"], at(b, kWainscotTop), at(a, kWainscotTop), at(a, kCeilingZ),
            at(b, kCeilingZ));
    // Moulding and skirting: boxes along the wall, standing a little into the room.
    const glm::vec3 inward = glm::normalize(glm::cross(kUp, b - a));
    const glm::vec3 lo = glm::min(a, b), hi = glm::max(a, b);
    const auto strip = [&](float z0, float z1, float depth) {
      const glm::vec3 q0 = glm::min(lo, lo + inward * depth),
                      q1 = glm::max(hi, hi + inward * depth);
      return box(glm::vec3(q0.x, q0.y, z0), glm::vec3(q1.x, q1.y, z1));
    };
    append(parts["moulding"], strip(kWainscotTop - 0.02f, kWainscotTop + 0.03f, 0.035f));
    append(parts["moulding"], strip(kFloorZ, kFloorZ + 0.14f, 0.02f));
  }
}

/// Floor and ceiling.
void floorAndCeiling(Parts& parts) {
  addQuad(parts["floor"], {-kHalfX, -kHalfY, kFloorZ}, {kHalfX, -kHalfY, kFloorZ},
          {kHalfX, kHalfY, kFloorZ}, {-kHalfX, kHalfY, kFloorZ});
  addQuad(parts["ceiling"], {-kHalfX, -kHalfY, kCeilingZ}, {-kHalfX, kHalfY, kCeilingZ},
          {kHalfX, kHalfY, kCeilingZ}, {kHalfX, -kHalfY, kCeilingZ});
}

/// A bar stool: a padded seat on a chrome post with a foot ring and a round base.
void stool(Parts& parts, glm::vec2 at) {
  const float seat_z = kStoolSeatZ;
  append(parts["stool_seat"], post(at, kStoolSeatRadius, seat_z - 0.08f, seat_z, 24));
  append(parts["chrome"], post(at, 0.025f, kFloorZ + 0.02f, seat_z - 0.08f, 10));
  append(parts["chrome"], post(at, 0.2f, kFloorZ, kFloorZ + 0.02f, 24));
  // The foot ring: a flat band around the post, on four spokes.
  MeshData ring = openFrustum(0.2f, 0.2f, 0.025f, 24);
  append(parts["chrome"],
         transformed(ring, glm::translate(glm::mat4(1.0f), glm::vec3(at, kFloorZ + 0.3f))));
  for (int k = 0; k < 4; ++k) {
    const float a = 1.5707963f * static_cast<float>(k);
    const glm::vec2 d(std::cos(a), std::sin(a));
    const glm::vec2 lo = at + glm::min(d * 0.2f, glm::vec2(0.0f)) - glm::vec2(0.008f);
    const glm::vec2 hi = at + glm::max(d * 0.2f, glm::vec2(0.0f)) + glm::vec2(0.008f);
    append(parts["chrome"], box(glm::vec3(lo, kFloorZ + 0.3f), glm::vec3(hi, kFloorZ + 0.315f)));
  }
}

/// The cue rack: a board on the wall with a shelf of sockets below and a comb above, six cues
/// standing in it.
void cueRack(Parts& parts, const WallPiece& piece) {
  const glm::mat4 frame = wallFrame(piece);
  const float half_w = piece.size.x * 0.5f, half_h = piece.size.y * 0.5f;
  append(parts["rack_wood"],
         transformed(box({-half_w, 0.0f, -half_h}, {half_w, 0.02f, half_h}), frame));
  const float shelf = -half_h + 0.05f, comb = half_h - 0.35f;
  append(parts["rack_wood"],
         transformed(box({-half_w, 0.02f, shelf - 0.04f}, {half_w, 0.12f, shelf}), frame));
  append(parts["rack_wood"],
         transformed(box({-half_w, 0.02f, comb - 0.03f}, {half_w, 0.10f, comb}), frame));
  for (int k = 0; k < 6; ++k) {
    const float x = -half_w + (static_cast<float>(k) + 0.5f) * piece.size.x / 6.0f;
    // Butt in the shelf's socket, shaft through the comb, leaning back a little.
    const glm::vec3 butt(x, 0.07f, shelf - 0.02f);
    MeshData butt_part = openFrustum(0.0145f, 0.0125f, 0.45f, 12);
    MeshData shaft = openFrustum(0.0125f, 0.0065f, 1.0f, 12);
    for (auto& p : shaft.positions) p.z += 0.45f;
    const glm::mat4 lean = glm::translate(frame, butt) *
                           glm::rotate(glm::mat4(1.0f), -0.03f, glm::vec3(1.0f, 0.0f, 0.0f));
    append(parts["rack_cue_butt"], transformed(butt_part, lean));
    append(parts["rack_cue_shaft"], transformed(shaft, lean));
  }
}

/// A bead scoreboard: a dark board, two brass wires, thirty beads slid to either end.
void scoreboard(Parts& parts, const WallPiece& piece) {
  const glm::mat4 frame = wallFrame(piece);
  const float half_w = piece.size.x * 0.5f, half_h = piece.size.y * 0.5f;
  append(parts["board"],
         transformed(box({-half_w, 0.0f, -half_h}, {half_w, 0.03f, half_h}), frame));
  for (int row = 0; row < 2; ++row) {
    const float z = (row == 0 ? 0.25f : -0.25f) * piece.size.y;
    append(parts["brass"], transformed(box({-half_w + 0.04f, 0.05f, z - 0.003f},
                                           {half_w - 0.04f, 0.056f, z + 0.003f}),
                                       frame));
    const int scored = row == 0 ? 6 : 4;  // beads slid to the left: that player's racks
    for (int k = 0; k < 15; ++k) {
      const float x = k < scored ? -half_w + 0.07f + 0.045f * static_cast<float>(k)
                                 : half_w - 0.07f - 0.045f * static_cast<float>(14 - k);
      append(
          parts[k % 5 == 4 ? "bead_dark" : "bead_light"],
          transformed(box({x - 0.02f, 0.035f, z - 0.02f}, {x + 0.02f, 0.075f, z + 0.02f}), frame));
    }
  }
}

/// A framed picture: a gilt frame around a canvas of sky over green hills.
void picture(Parts& parts, const WallPiece& piece) {
  const glm::mat4 frame = wallFrame(piece);
  const float half_w = piece.size.x * 0.5f, half_h = piece.size.y * 0.5f, border = 0.06f;
  const glm::vec3 lo(-half_w, 0.0f, -half_h), hi(half_w, 0.04f, half_h);
  append(parts["gilt"], transformed(box(lo, {hi.x, hi.y, lo.z + border}), frame));
  append(parts["gilt"], transformed(box({lo.x, lo.y, hi.z - border}, hi), frame));
  append(parts["gilt"], transformed(box(lo, {lo.x + border, hi.y, hi.z}), frame));
  append(parts["gilt"], transformed(box({hi.x - border, lo.y, lo.z}, hi), frame));
  const float x0 = -half_w + border, x1 = half_w - border;
  const float z0 = -half_h + border, z1 = half_h - border, horizon = z0 + 0.45f * (z1 - z0);
  const float y = 0.015f;
  MeshData sky, land;
  addQuad(sky, {x0, y, horizon}, {x1, y, horizon}, {x1, y, z1}, {x0, y, z1});
  // The hills: a wavy horizon, one quad per strip.
  constexpr int kStrips = 12;
  for (int i = 0; i < kStrips; ++i) {
    const float a = x0 + (x1 - x0) * static_cast<float>(i) / kStrips;
    const float b = x0 + (x1 - x0) * static_cast<float>(i + 1) / kStrips;
    const auto hill = [&](float x) {
      return horizon + 0.06f * std::sin(x * 9.0f + piece.centre.x) + 0.03f;
    };
    addQuad(land, {a, y + 0.001f, z0}, {b, y + 0.001f, z0}, {b, y + 0.001f, hill(b)},
            {a, y + 0.001f, hill(a)});
  }
  // Seen from the room: the quads face -y in the piece's frame, toward the viewer, as built.
  append(parts["canvas_sky"], transformed(sky, frame));
  append(parts["canvas_land"], transformed(land, frame));
}

}  // namespace

bool isHallShell(const std::string& name) {
  return name == "floor" || name == "ceiling" || name == "wainscot" || name == "wallpaper";
}

std::vector<NamedMesh> hallRoom() {
  Parts parts;
  floorAndCeiling(parts);
  walls(parts);
  for (const glm::vec2& at : kStools) stool(parts, at);
  for (const WallPiece& piece : kWallPieces) {
    const std::string name = piece.name;
    if (name == "cue_rack") cueRack(parts, piece);
    if (name == "scoreboard") scoreboard(parts, piece);
    if (name == "picture") picture(parts, piece);
  }
  return parts.take();
}

}  // namespace pool::render
