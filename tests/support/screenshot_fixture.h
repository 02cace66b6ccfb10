// The fixture of the screenshot tests: pool-client --screenshot under Xvfb into a scratch PNG.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/display_check.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/xvfb_run.h"

namespace pool::client::test {

/// Renders pool-client --screenshot under Xvfb into a scratch PNG and decodes it.
class ScreenshotTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system("command -v xvfb-run >/dev/null 2>&1") != 0) {
      POOL_NO_DISPLAY("xvfb-run is not installed");
    }
    png_ = "/tmp/pool-render-test-" + std::to_string(::getpid()) + ".png";
  }
  void TearDown() override {
    if (!png_.empty() && !std::getenv("POOL_KEEP_TEST_FILES")) std::remove(png_.c_str());
  }
  /// Renders with `extra` flags and decodes the result (empty image on failure).
  Image screenshot(const std::string& extra) const {
    const std::string cmd = pool::test::xvfbRun() + std::string(" -s \"-screen 0 1280x720x24\" ") +
                            POOL_BIN_DIR + "/pool-client --screenshot " + png_ + " " + extra;
    EXPECT_EQ(std::system(cmd.c_str()), 0) << cmd;
    return loadPng(png_);
  }
  std::string png_;
};

/// A screenshot test that also reads the sidecar (--screenshot-info) for the camera.
class ScreenshotInfoTest : public ScreenshotTest {
 protected:
  void TearDown() override {
    if (!std::getenv("POOL_KEEP_TEST_FILES")) std::remove(info().c_str());
    ScreenshotTest::TearDown();
  }
  std::string info() const { return png_ + ".json"; }
  /// Renders with `flags` and keeps the reported camera in camera_.
  Image view(const std::string& flags) {
    const Image image = screenshot("--screenshot-info " + info() + " " + flags);
    camera_ = reportedCamera(readInfo(info()));
    return image;
  }
  ReportedCamera camera_;
};

}  // namespace pool::client::test
