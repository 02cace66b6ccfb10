// The cue's shadow: its axis cut into pieces, each projected from the lamp onto the slate.
#include "client/render/cue_shadow.h"

#include <cmath>

#include "client/render/cue_profile.h"
#include "client/render/lamps.h"

namespace pool::render {

namespace {

constexpr int kPieces = 30;
constexpr float kMinShare = 0.02f;  // lamps giving less of the light cast no shadow

/// Where the ray from the light through `p` meets the slate, and how much a width at `p` grows
/// there; empty-scale (0) when `p` is not below the light.
glm::vec3 onSlate(glm::vec3 lamp, glm::vec3 p) {
  const float drop = lamp.z - p.z;
  if (drop <= 0.0f) return glm::vec3(0.0f);
  const float grow = lamp.z / drop;
  const glm::vec3 q = lamp + (p - lamp) * grow;
  return {q.x, q.y, grow};
}

}  // namespace

std::vector<ShadowBlob> cueShadow(std::span<const glm::vec3> lamps, const CuePlacement& cue,
                                  float half_length, float half_width, float ambient) {
  std::vector<ShadowBlob> out;
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  const auto length = static_cast<float>(cueLength());
  for (const glm::vec3& lamp : lamps) {
    for (int i = 0; i < kPieces; ++i) {
      const float s0 = length * static_cast<float>(i) / kPieces;
      const float s1 = length * static_cast<float>(i + 1) / kPieces;
      const glm::vec3 a = onSlate(lamp, cue.tip - cue.forward * s0);
      const glm::vec3 b = onSlate(lamp, cue.tip - cue.forward * s1);
      if (a.z <= 0.0f || b.z <= 0.0f) continue;
      const glm::vec2 mid = (glm::vec2(a) + glm::vec2(b)) * 0.5f;
      if (std::abs(mid.x) > half_length || std::abs(mid.y) > half_width) continue;
      const glm::vec2 along = glm::vec2(b) - glm::vec2(a);
      if (glm::length(along) < 1e-6f) continue;
      const glm::vec3 at(mid, 0.0f);
      float total = ambient;
      for (const glm::vec3& other : lamps) total += lampLight(other, at, up);
      const float share = lampLight(lamp, at, up) / total;
      if (share < kMinShare) continue;
      const float radius = static_cast<float>(cueRadiusAt((s0 + s1) * 0.5f));
      out.push_back({mid, glm::normalize(along), glm::length(along) * 0.5f,
                     radius * (a.z + b.z) * 0.5f, share, false});
    }
  }
  return out;
}

}  // namespace pool::render
