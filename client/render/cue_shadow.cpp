// The cue's shadow: its axis cut into pieces, each projected from the lamp onto the slate.
#include "client/render/cue_shadow.h"

#include <cmath>

#include "client/render/cue_profile.h"
#include "client/render/lamps.h"

namespace pool::render {

namespace {

constexpr int kPieces = 30;
constexpr float kMinShare = 0.02f;  // lamps giving less of the light cast no shadow

/// Where the ray from the light through `p` meets the plane z = `surface`, and how much a width
/// at `p` grows there; empty-scale (0) when `p` is not between the light and the plane.
glm::vec3 onPlane(glm::vec3 lamp, glm::vec3 p, float surface) {
  const float drop = lamp.z - p.z;
  if (drop <= 0.0f || p.z <= surface) return glm::vec3(0.0f);
  const float grow = (lamp.z - surface) / drop;
  const glm::vec3 q = lamp + (p - lamp) * grow;
  return {q.x, q.y, grow};
}

/// The strip on the plane z = `surface`, the pieces whose middle `keep` accepts.
template <class Keep>
std::vector<ShadowBlob> strip(std::span<const glm::vec3> lamps, const CuePlacement& cue,
                              float surface, float ambient, Keep keep) {
  std::vector<ShadowBlob> out;
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  const auto length = static_cast<float>(cueLength());
  for (const glm::vec3& lamp : lamps) {
    for (int i = 0; i < kPieces; ++i) {
      const float s0 = length * static_cast<float>(i) / kPieces;
      const float s1 = length * static_cast<float>(i + 1) / kPieces;
      const glm::vec3 a = onPlane(lamp, cue.tip - cue.forward * s0, surface);
      const glm::vec3 b = onPlane(lamp, cue.tip - cue.forward * s1, surface);
      if (a.z <= 0.0f || b.z <= 0.0f) continue;
      const glm::vec2 mid = (glm::vec2(a) + glm::vec2(b)) * 0.5f;
      if (!keep(mid)) continue;
      const glm::vec2 along = glm::vec2(b) - glm::vec2(a);
      if (glm::length(along) < 1e-6f) continue;
      const glm::vec3 at(mid, surface);
      float total = ambient;
      for (const glm::vec3& other : lamps) total += lampLight(other, at, up);
      const float share = lampLight(lamp, at, up) / total;
      if (share < kMinShare) continue;
      const float radius = static_cast<float>(cueRadiusAt((s0 + s1) * 0.5f));
      out.push_back({mid, glm::normalize(along), glm::length(along) * 0.5f,
                     radius * (a.z + b.z) * 0.5f, share, false, surface});
    }
  }
  return out;
}

}  // namespace

std::vector<ShadowBlob> cueShadow(std::span<const glm::vec3> lamps, const CuePlacement& cue,
                                  float half_length, float half_width, float ambient) {
  return strip(lamps, cue, 0.0f, ambient, [&](glm::vec2 mid) {
    return std::abs(mid.x) <= half_length && std::abs(mid.y) <= half_width;
  });
}

std::vector<ShadowBlob> cueShadowOnRails(std::span<const glm::vec3> lamps, const CuePlacement& cue,
                                         const RailExtent& rails, float ambient) {
  const float outer = rails.cushion_width + rails.rail_width;
  return strip(lamps, cue, rails.top, ambient, [&](glm::vec2 mid) {
    const bool over_felt =
        std::abs(mid.x) <= rails.half_length && std::abs(mid.y) <= rails.half_width;
    const bool on_table =
        std::abs(mid.x) <= rails.half_length + outer && std::abs(mid.y) <= rails.half_width + outer;
    return on_table && !over_felt;
  });
}

}  // namespace pool::render
