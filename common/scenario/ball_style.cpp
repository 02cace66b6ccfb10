// The plot's ball colours: the usual set of American pool balls, a snooker set, a carom set.
#include "scenario/ball_style.h"

#include <array>

namespace pool::scenario {

BallStyle ballStyle(int id) {
  // Index 1-7: the solids' colours, shared by the stripes 9-15. Green is brightened to show on the
  // cloth.
  static const std::array<const char*, 8> kColours = {"#ffffff", "#f2c200", "#1e4fd0", "#d42222",
                                                      "#7a2fa0", "#f07800", "#22c860", "#8a1c24"};
  if (id == 0) return {"#ffffff", false, true};
  if (id == 8) return {"#111111", false, false};
  if (id >= 1 && id <= 7) return {kColours[static_cast<std::size_t>(id)], false, false};
  if (id >= 9 && id <= 15) return {kColours[static_cast<std::size_t>(id - 8)], true, false};
  return {"#888888", false, false};
}

BallStyle ballStyle(int id, const table::TableSpec& spec) {
  if (id == 0) return {"#ffffff", false, true};
  if (spec.snooker_marks) {
    // The colours in their order of value; the green brightened to show on the cloth.
    static const std::array<const char*, 6> kColours = {"#f2c200", "#2fae55", "#7a4a22",
                                                        "#1e4fd0", "#f08fb0", "#111111"};
    if (id >= 1 && id <= 15) return {"#c01818", false, false};
    if (id >= 16 && id <= 21) return {kColours[static_cast<std::size_t>(id - 16)], false, false};
    return {"#888888", false, false};
  }
  if (!spec.pockets) {
    if (id == 1) return {"#f2c200", false, false};
    if (id == 2) return {"#d42222", false, false};
    return {"#888888", false, false};
  }
  return ballStyle(id);
}

}  // namespace pool::scenario
