// The xvfb-run command line of a test module: displays from its own base (POOL_XVFB_DISPLAY_BASE,
// set per module by tests/CMakeLists.txt), so modules that start Xvfb can run side by side.
#pragma once

#include <string>

#ifndef POOL_XVFB_DISPLAY_BASE
#define POOL_XVFB_DISPLAY_BASE 99
#endif

namespace pool::test {

/// "xvfb-run -n BASE -a": the first free display from the module's base (two `xvfb-run -a`
/// started at once from the same base can pick the same display; the module's own tests run one
/// at a time, and other modules start from bases of their own).
inline std::string xvfbRun() {
  return "xvfb-run -n " + std::to_string(POOL_XVFB_DISPLAY_BASE) + " -a";
}

}  // namespace pool::test
