// The shared break scene run through the real physics once: its event log, for the audio tests.
#pragma once

#include <cmath>
#include <stdexcept>

#include "physics/events.h"
#include "scenario/scenario.h"

namespace pool::audio::test {

/// The events of assets/scenes/break.json from strike to rest.
inline const physics::EventLog& breakEvents() {
  static const physics::EventLog events = [] {
    auto scene = scenario::loadScenario("break");
    if (!scene) throw std::runtime_error(scene.error());
    auto outcome = scenario::runScenario(*scene);
    if (!outcome) throw std::runtime_error(outcome.error());
    return outcome->events;
  }();
  return events;
}

/// One event of a type at a time and speed.
inline physics::Event event(physics::EventType type, double t, double speed, int ball = 1) {
  physics::Event e;
  e.type = type;
  e.t = t;
  e.speed = speed;
  e.ball_a = ball;
  return e;
}

/// Root mean square of samples.
template <class Samples>
double rms(const Samples& s) {
  double sum = 0.0;
  for (float x : s) sum += static_cast<double>(x) * x;
  return s.empty() ? 0.0 : std::sqrt(sum / static_cast<double>(s.size()));
}

}  // namespace pool::audio::test
