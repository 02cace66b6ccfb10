// The plot's ball colours, the usual set of American pool balls.
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

}  // namespace pool::scenario
