// The palette: felt, wood and pocket colours, and the standard ball colours.
#include "client/render/palette.h"

#include <array>

#include "client/render/shaders.h"
#include "physics/ball.h"
#include "table/snooker_spots.h"

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

/// Snooker's colours 16–21 (the reds 1–15 share kSnookerRed), chosen to read apart under the
/// lamps: the reds a deep red, the pink light and bluish beside them, the brown dark and
/// orange-tinged between the reds and the black, the green a third darker than the cloth.
constexpr glm::vec3 kSnookerRed(0.68f, 0.03f, 0.035f);
constexpr std::array<glm::vec3, 6> kSnookerColours{{
    {0.96f, 0.76f, 0.04f},     // 16 yellow
    {0.01f, 0.24f, 0.10f},     // 17 green
    {0.32f, 0.16f, 0.05f},     // 18 brown
    {0.03f, 0.12f, 0.72f},     // 19 blue
    {0.98f, 0.45f, 0.60f},     // 20 pink
    {0.025f, 0.025f, 0.025f},  // 21 black
}};
constexpr int kSnookerReds = 15;
static_assert(kSnookerReds + static_cast<int>(kSnookerColours.size()) == physics::kMaxBallId,
              "a snooker set's black is the highest ball id the physics knows");

bool startsWith(const std::string& s, const char* prefix) {
  return s.rfind(prefix, 0) == 0;
}

}  // namespace

BallSet ballSetOf(const table::TableSpec& spec) {
  if (table::snookerSpotsFor(spec)) return BallSet::Snooker;
  return spec.pockets ? BallSet::Pool : BallSet::Carom;
}

int maxBallIdOf(BallSet set) {
  switch (set) {
    case BallSet::Carom:
      return 2;
    case BallSet::Snooker:
      return kSnookerReds + static_cast<int>(kSnookerColours.size());
    case BallSet::Pool:
      break;
  }
  return 15;
}

BallLook ballLook(int id, BallSet set) {
  if (set == BallSet::Snooker) {
    if (id >= 1 && id <= kSnookerReds) return {kSnookerRed, false, 0};
    if (id > kSnookerReds && id <= maxBallIdOf(set)) {
      return {kSnookerColours[static_cast<std::size_t>(id - kSnookerReds - 1)], false, 0};
    }
    return {kWhite, false, 0};
  }
  if (set == BallSet::Carom) {
    // UMB: a white, a yellow (or a spotted white) and a red, unnumbered.
    if (id == 1) return {{0.93f, 0.72f, 0.05f}, false, 0};
    if (id == 2) return {{0.72f, 0.03f, 0.03f}, false, 0};
    return {kWhite, false, 0};
  }
  if (id <= 0 || id > 15) return {kWhite, false, 0};
  if (id <= 8) return {kSolids[static_cast<std::size_t>(id - 1)], false, id};
  return {kSolids[static_cast<std::size_t>(id - 9)], true, id};
}

PartLook partLook(const std::string& part_name) {
  if (part_name == "slate") return {kFelt, shaders::kFelt};
  if (startsWith(part_name, "cushion_") || startsWith(part_name, "jaw_")) {
    return {kCushion, shaders::kFelt};
  }
  if (startsWith(part_name, "rail_") || part_name == "trough") return {kWood, shaders::kWood};
  return {kDark, shaders::kPlain};
}

glm::vec3 chalkColour() {
  return {0.80f, 0.82f, 0.76f};
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

PartLook hallPartLook(const std::string& name) {
  struct Entry {
    const char* name;
    PartLook look;
  };
  static const Entry kLooks[] = {
      // The table's dressing.
      {"rail_top", {kWood, shaders::kWood}},
      {"rail_edge", {kWood, shaders::kWood}},
      {"apron", {kWood, shaders::kWood}},
      {"leg", {kWood, shaders::kWood}},
      {"underside", {{0.05f, 0.04f, 0.03f}, shaders::kRoomPlain}},
      {"pocket_liner", {{0.11f, 0.065f, 0.04f}, shaders::kLiner}},
      {"pocket_rim", {{0.05f, 0.035f, 0.025f}, shaders::kPlain}},
      // The hall.
      {"floor", {{0.40f, 0.23f, 0.11f}, shaders::kFloor}},
      {"ceiling", {{0.16f, 0.13f, 0.11f}, shaders::kRoomPlain}},
      {"wainscot", {{0.34f, 0.17f, 0.08f}, shaders::kRoomWood}},
      {"moulding", {{0.24f, 0.11f, 0.05f}, shaders::kRoomWood}},
      {"wallpaper", {{0.55f, 0.15f, 0.12f}, shaders::kWall}},
      {"stool_seat", {{0.50f, 0.06f, 0.05f}, shaders::kRoomPlain}},
      {"chrome", {{0.72f, 0.72f, 0.75f}, shaders::kRoomPlain}},
      {"rack_wood", {{0.38f, 0.19f, 0.08f}, shaders::kRoomWood}},
      {"rack_cue_shaft", {{0.86f, 0.69f, 0.45f}, shaders::kRoomPlain}},
      {"rack_cue_butt", {{0.30f, 0.09f, 0.04f}, shaders::kRoomPlain}},
      {"board", {{0.14f, 0.08f, 0.04f}, shaders::kRoomWood}},
      {"brass", {{0.80f, 0.66f, 0.30f}, shaders::kRoomPlain}},
      {"bead_light", {{0.92f, 0.88f, 0.76f}, shaders::kRoomPlain}},
      {"bead_dark", {{0.10f, 0.08f, 0.07f}, shaders::kRoomPlain}},
      {"gilt", {{0.74f, 0.57f, 0.24f}, shaders::kRoomPlain}},
      {"canvas_sky", {{0.55f, 0.63f, 0.72f}, shaders::kRoomPlain}},
      {"canvas_land", {{0.24f, 0.38f, 0.17f}, shaders::kRoomPlain}},
  };
  for (const Entry& e : kLooks) {
    if (name == e.name) return e.look;
  }
  return {{0.5f, 0.5f, 0.5f}, shaders::kRoomPlain};
}

}  // namespace pool::render
