// Shared scenes run through the real physics for the audio tests: event logs and 60 Hz frames.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

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

/// A scene's shot with 60 Hz frames as the server sends them: every sample, then the table at
/// rest when the shot ended.
inline physics::ShotOutcome framedShot(const std::string& scene) {
  auto s = scenario::loadScenario(scene);
  if (!s) throw std::runtime_error(s.error());
  s->options.sample_hz = 60.0;
  auto outcome = scenario::runScenario(*s);
  if (!outcome) throw std::runtime_error(outcome.error());
  const double last = outcome->trajectory.back().t;
  outcome->trajectory.push_back({std::max(last, outcome->t_rest.value_or(last)), outcome->balls});
  return *outcome;
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
