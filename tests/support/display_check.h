// What a test does when it cannot have a display, a context or another part of the machine's setup:
// skip on a developer's machine, fail in CI (CI=true), where a missing piece must not pass
// unnoticed.
#pragma once

#include <gtest/gtest.h>

#include "support/ci_env.h"

/// Ends the current test (or its SetUp) for want of a display: a failure in CI, a skip elsewhere.
/// `reason` is streamed into the message.
#define POOL_NO_DISPLAY(reason)                                                                 \
  do {                                                                                          \
    if (::pool::test::runningInCi()) {                                                          \
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
    if (::pool::test::runningInCi()) {                                                         \
      GTEST_FAIL() << reason << " (CI=true: this test must run; scripts/deps.sh installs it)"; \
    } else {                                                                                   \
      GTEST_SKIP() << reason << " (skipped; with CI=true this fails)";                         \
    }                                                                                          \
  } while (0)
