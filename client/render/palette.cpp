// The palette: felt, wood and pocket colours, and the standard ball colours.
#include "client/render/palette.h"

#include <array>

#include "client/render/shaders.h"

namespace pool::render {

namespace {

constexpr glm::vec3 kFelt(0.05f, 0.42f, 0.20f);
constexpr glm::vec3 kCushion(0.04f, 0.36f, 0.17f);
constexpr glm::vec3 kWood(0.42f, 0.21f, 0.086f);
constexpr glm::vec3 kDark(0.02f, 0.02f, 0.02f);
constexpr glm::vec3 kWhite(0.95f, 0.95f, 0.92f);

/// Colours of balls 1–8 (stripes 9–15 reuse those of n − 8).
constexpr std::array<glm::vec3, 8> kSolids{{
    {0.98f, 0.80f, 0.05f},  // 1 yellow
    {0.05f, 0.15f, 0.80f},  // 2 blue
    {0.85f, 0.05f, 0.05f},  // 3 red
    {0.40f, 0.10f, 0.60f},  // 4 purple
    {1.00f, 0.45f, 0.02f},  // 5 orange
    {0.02f, 0.55f, 0.08f},  // 6 green
    {0.45f, 0.04f, 0.10f},  // 7 maroon
    {0.03f, 0.03f, 0.03f},  // 8 black
}};

bool startsWith(const std::string& s, const char* prefix) {
  return s.rfind(prefix, 0) == 0;
}

}  // namespace

BallLook ballLook(int id) {
  if (id <= 0 || id > 15) return {kWhite, false};
  if (id <= 8) return {kSolids[static_cast<std::size_t>(id - 1)], false};
  return {kSolids[static_cast<std::size_t>(id - 9)], true};
}

PartLook partLook(const std::string& part_name) {
  if (part_name == "slate") return {kFelt, shaders::kFelt};
  if (startsWith(part_name, "cushion_") || startsWith(part_name, "jaw_")) {
    return {kCushion, shaders::kFelt};
  }
  if (startsWith(part_name, "rail_") || part_name == "trough") return {kWood, shaders::kWood};
  return {kDark, shaders::kPlain};
}

glm::vec3 woodColour() {
  return kWood;
}

glm::vec3 shadeColour() {
  return {0.42f, 0.07f, 0.06f};  // oxblood enamel
}

glm::vec3 bulbColour() {
  return {1.0f, 0.96f, 0.85f};
}

glm::vec3 holeColour() {
  return kDark;
}

}  // namespace pool::render
