// libFuzzer target: the physics lab's scenario parser (pool-sim's JSON input) on any text.
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "scenario/scenario.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto parsed = pool::scenario::parseScenario(text);
  if (!parsed) {
    // A refusal is one non-empty line (SIM-CONTRACT.md).
    const std::string& why = parsed.error();
    if (why.empty() || why.find('\n') != std::string::npos) {
      std::fprintf(stderr, "refusal is not one line: '%s'\n", why.c_str());
      std::abort();
    }
    return 0;
  }
  // An accepted scenario has balls sorted by id, each id once, and a cue ball.
  const auto& balls = parsed->balls;
  for (std::size_t i = 1; i < balls.size(); ++i) {
    if (!(balls[i - 1].id < balls[i].id)) {
      std::fprintf(stderr, "balls not sorted by unique id\n");
      std::abort();
    }
  }
  if (balls.empty() || balls.front().id != 0) {
    std::fprintf(stderr, "accepted a scenario without a cue ball\n");
    std::abort();
  }
  return 0;
}
