// pool-client --spectate MATCH --screenshot FILE: follow a match over DDS and render what the
// server's snapshots show, offscreen, into a PNG (and the JSON sidecar of what was drawn).
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "client/render/screenshot.h"

namespace pool::client {

/// Which match to follow and how long to wait for it.
struct SpectateScreenshotConfig {
  std::uint32_t domain = 0;
  std::string match = "any";                     ///< a match id, or "any": the first in play
  double timeout = 0.0;                          ///< s to wait for the match's table; 0: no limit
  std::function<bool()> stop;                    ///< true: give up (a signal came)
  std::function<void(const std::string&)> emit;  ///< the spectator's JSON lines; may be empty
};

/// Joins as a spectator, waits for the match's table, then renders the screenshot's frames with
/// the latest balls before each. Exit codes: 0 done, 1 render or DDS error, 3 timed out or stopped.
int runSpectateScreenshot(const SpectateScreenshotConfig& config,
                          const render::ScreenshotOptions& options);

}  // namespace pool::client
