// Names of the motion states, as SIM-CONTRACT.md spells them.
#include "physics/ball.h"

#include <array>
#include <utility>

namespace pool::physics {

namespace {
constexpr std::array<std::pair<MotionState, const char*>, 7> kNames{{
    {MotionState::Stationary, "stationary"},
    {MotionState::Spinning, "spinning"},
    {MotionState::Sliding, "sliding"},
    {MotionState::Rolling, "rolling"},
    {MotionState::Airborne, "airborne"},
    {MotionState::Pocketed, "pocketed"},
    {MotionState::OffTable, "off_table"},
}};
}  // namespace

const char* toString(MotionState state) {
  for (const auto& [s, name] : kNames) {
    if (s == state) return name;
  }
  return "unknown";
}

std::optional<MotionState> motionStateFromString(std::string_view name) {
  for (const auto& [s, n] : kNames) {
    if (name == n) return s;
  }
  return std::nullopt;
}

}  // namespace pool::physics
