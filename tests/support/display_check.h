// What a test does when it cannot have a display, a context or another part of the machine's setup:
// skip on a developer's machine, fail in CI (CI=true), where a missing piece must not pass
// unnoticed.
#pragma once

#include <gtest/gtest.h>

#include <cstdlib>
#include <string_view>

namespace pool::client::test {

/// True when the CI environment variable is "true" (as GitHub Actions, GitLab CI and most other
/// CI services set it).
inline bool runningInCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string_view(ci) == "true";
}

}  // namespace pool::client::test

/// Ends the current test (or its SetUp) for want of a display: a failure in CI, a skip elsewhere.
/// `reason` is streamed into the message.
#define POOL_NO_DISPLAY(reason)                                                                 \
  do {                                                                                          \
    if (::pool::client::test::runningInCi()) {                                                  \
      GTEST_FAIL() << reason << " (CI=true: the OpenGL tests must run; install xvfb and Mesa)"; \
    } else {                                                                                    \
      GTEST_SKIP() << reason << " (skipped; with CI=true this fails)";                          \
    }                                                                                           \
  } while (0)

/// Ends the current test (or its SetUp) for want of something scripts/deps.sh installs (a font, a
/// tool): a failure in CI, a skip elsewhere, as for the display. `reason` is streamed into the
/// message.
#define POOL_MISSING_SETUP(reason)                                                             \
  do {                                                                                         \
    if (::pool::client::test::runningInCi()) {                                                 \
      GTEST_FAIL() << reason << " (CI=true: this test must run; scripts/deps.sh installs it)"; \
    } else {                                                                                   \
      GTEST_SKIP() << reason << " (skipped; with CI=true this fails)";                         \
    }                                                                                          \
  } while (0)
