// The --screenshot mode: render a scene offscreen for a few frames and write the last as PNG.
#pragma once

#include <string>

#include "client/render/renderer.h"

namespace pool::render {

/// What to render and where to write it.
struct ScreenshotOptions {
  std::string path;            ///< PNG file to write
  int frames = 3;              ///< frames to render; the last one is written
  std::string scene = "rack";  ///< only "rack" for now
  RenderOptions render;        ///< wireframe, textures, lighting
  int width = 1280;
  int height = 720;
};

/// Renders and writes the PNG. Returns the process exit code (0 on success); errors go to stderr.
int runScreenshot(const ScreenshotOptions& options);

}  // namespace pool::render
