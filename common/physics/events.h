// The ordered, typed log of what happened during a shot: what rules, server and tests read.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "physics/ball.h"

namespace pool::physics {

enum class EventType : std::uint8_t {
  Strike,       ///< the cue hits the ball struck (ball_a: the cue ball, 0, but in three-cushion)
  BallBall,     ///< ball_a hits ball_b
  BallCushion,  ///< ball_a hits a cushion or jaw (`where` = its name)
  Pocket,       ///< ball_a drops into a pocket (`where` = the pocket's name)
  SlideToRoll,  ///< ball_a starts rolling without slip
  RollToRest,   ///< ball_a stops (it may still spin in place: then SpinToRest follows)
  SpinToRest,   ///< ball_a's spin about the vertical stops
  Airborne,     ///< ball_a leaves the slate
  Land,         ///< ball_a lands back on the slate
  OffTable,     ///< ball_a leaves the table
  Respot,       ///< the watchdog re-spotted or removed ball_a (`where` says why)
};

const char* toString(EventType type);  ///< snake_case names of SIM-CONTRACT.md
std::optional<EventType> eventTypeFromString(std::string_view name);

/// One event. Times in seconds from the strike.
struct Event {
  double t = 0.0;
  EventType type = EventType::Strike;
  int ball_a = 0;
  int ball_b = -1;          ///< the other ball of a BallBall event, else -1
  std::string where;        ///< cushion, jaw or pocket name, or the watchdog's reason
  double speed = 0.0;       ///< closing speed along the contact normal at impact, m/s (0 if none)
  Vec3 pos = Vec3::Zero();  ///< ball_a's centre at the event, table frame, m
};

using EventLog = std::vector<Event>;

}  // namespace pool::physics
