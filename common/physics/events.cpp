// Names of the event types, as SIM-CONTRACT.md spells them.
#include "physics/events.h"

#include <array>
#include <utility>

namespace pool::physics {

namespace {
constexpr std::array<std::pair<EventType, const char*>, 11> kNames{{
    {EventType::Strike, "strike"},
    {EventType::BallBall, "ball_ball"},
    {EventType::BallCushion, "ball_cushion"},
    {EventType::Pocket, "pocket"},
    {EventType::SlideToRoll, "slide_to_roll"},
    {EventType::RollToRest, "roll_to_rest"},
    {EventType::SpinToRest, "spin_to_rest"},
    {EventType::Airborne, "airborne"},
    {EventType::Land, "land"},
    {EventType::OffTable, "off_table"},
    {EventType::Respot, "respot"},
}};
}  // namespace

const char* toString(EventType type) {
  for (const auto& [t, name] : kNames) {
    if (t == type) return name;
  }
  return "unknown";
}

std::optional<EventType> eventTypeFromString(std::string_view name) {
  for (const auto& [t, n] : kNames) {
    if (name == n) return t;
  }
  return std::nullopt;
}

}  // namespace pool::physics
