// Where a shot's CPU time goes, by part of the engine: measured only when a benchmark asks.
#pragma once

#include <array>
#include <chrono>
#include <cstddef>
#include <cstdint>

#if defined(__x86_64__)
#include <x86intrin.h>
#endif

namespace pool::physics {

/// The parts of the engine a shot's time is split into.
enum class Part : std::size_t {
  Other,        ///< the loop's own bookkeeping, setup and finish
  Prediction,   ///< event prediction: root finding for pairs and table features, next event
  Integration,  ///< our side of a step: forces, exact position correction, orientations, samples
  Ode,          ///< ODE itself: dWorldStep and body updates
  Resolution,   ///< contacts and transitions: ball–ball, the break's cluster, cushions, slate
  Watchdog,     ///< the checks after every event
  Pockets,      ///< the pocket world's steps: falling balls, stepped and settled
  PocketSetup,  ///< making the pocket world at a shot's first drop
};
inline constexpr std::size_t kPartCount = 8;

/// A part's name for reports: "prediction", "pocket setup", ...
inline const char* partName(Part part) {
  constexpr const char* kPartNames[kPartCount] = {"other",   "prediction",  "integration",
                                                  "ode",     "resolution",  "watchdog",
                                                  "pockets", "pocket setup"};
  return kPartNames[static_cast<std::size_t>(part)];
}

/// Seconds spent in each part (exclusive: a part called from another is charged to itself).
using PartTimes = std::array<double, kPartCount>;

/// Charges the time between switches to the part that was running. Off (the default), a switch
/// costs one branch and reads no clock, so the simulation's results never depend on it. On x86-64
/// the switches read the time-stamp counter (a few nanoseconds), converted to seconds by the
/// steady clock read at start and stop. Times are wall-clock: on a loaded machine they include
/// the time the thread was preempted, so their shares are the figure to read.
class Profiler {
 public:
  using Clock = std::chrono::steady_clock;

  void start() {
    on_ = true;
    ticks_.fill(0);
    current_ = Part::Other;
    started_ = Clock::now();
    first_ = last_ = ticks();
  }
  /// Stops, charging the running part, and returns the times in seconds.
  PartTimes stop() {
    PartTimes seconds{};
    if (!on_) return seconds;
    switchTo(Part::Other);
    on_ = false;
    const double elapsed = std::chrono::duration<double>(Clock::now() - started_).count();
    const auto span = static_cast<double>(last_ - first_);
    const double per_tick = span > 0 ? elapsed / span : 0.0;
    for (std::size_t p = 0; p < kPartCount; ++p) {
      seconds[p] = per_tick * static_cast<double>(ticks_[p]);
    }
    return seconds;
  }
  /// Makes `part` the running one; returns the one that was.
  Part switchTo(Part part) {
    if (!on_) return part;
    const std::uint64_t now = ticks();
    ticks_[static_cast<std::size_t>(current_)] += now - last_;
    last_ = now;
    const Part previous = current_;
    current_ = part;
    return previous;
  }

 private:
  static std::uint64_t ticks() {
#if defined(__x86_64__)
    return __rdtsc();
#else
    return static_cast<std::uint64_t>(Clock::now().time_since_epoch().count());
#endif
  }

  bool on_ = false;
  Part current_ = Part::Other;
  Clock::time_point started_;
  std::uint64_t first_ = 0, last_ = 0;
  std::array<std::uint64_t, kPartCount> ticks_{};
};

/// Runs `part` for the life of the scope, then the part that was running before.
class PartScope {
 public:
  PartScope(Profiler& profiler, Part part)
      : profiler_(profiler), previous_(profiler.switchTo(part)) {}
  ~PartScope() { profiler_.switchTo(previous_); }
  PartScope(const PartScope&) = delete;
  PartScope& operator=(const PartScope&) = delete;

 private:
  Profiler& profiler_;
  Part previous_;
};

}  // namespace pool::physics
