// libFuzzer target: the physics lab's scenario parser (pool-sim's JSON input) on any text.
#include <cstddef>
#include <cstdint>
#include <string>

#include "broken_promise.h"
#include "scenario/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto parsed = pool::scenario::parseScenario(text);
  if (!parsed) {
    pool::fuzz::expectOneLineReason(parsed.error());  // SIM-CONTRACT.md
    return 0;
  }
  // An accepted scenario has balls sorted by id, each id once, and a cue ball.
  const auto& balls = parsed->balls;
  for (std::size_t i = 1; i < balls.size(); ++i) {
    if (!(balls[i - 1].id < balls[i].id))
      pool::fuzz::brokenPromise("balls not sorted by unique id");
  }
  if (balls.empty() || balls.front().id != 0) pool::fuzz::brokenPromise("accepted no cue ball");
  return 0;
}
