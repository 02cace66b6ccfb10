// The --screenshot mode: render a scene offscreen for a few frames and write the last as PNG,
// optionally with a JSON sidecar of the camera and the balls as drawn.
#pragma once

#include <cstdint>
#include <functional>
#include <string>

#include "client/render/renderer.h"

namespace pool::render {

/// What to render and where to write it.
struct ScreenshotOptions {
  std::string path;            ///< PNG file to write
  std::string info_path;       ///< JSON sidecar (camera, image size, balls drawn); empty: none
  int frames = 3;              ///< frames to render; the last one is written
  std::string scene = "rack";  ///< "rack" or "eightball" (ignored when spectating)
  std::string question = "Will I win?";  ///< asked in the eightball scene
  std::uint64_t seed = 0;                ///< the Magic Eight Ball's seed
  RenderOptions render;                  ///< wireframe, textures, lighting
  int width = 1280;
  int height = 720;
};

/// Called before each frame (0-based) to bring the renderer's balls up to date.
using FrameHook = std::function<void(Renderer& renderer, int frame)>;

/// Renders `scene` from the overview camera and writes the PNG (and the sidecar). Returns the
/// process exit code (0 on success); errors go to stderr as one line.
int renderScreenshot(const ScreenshotOptions& options, const Scene& scene,
                     const FrameHook& before_frame = {});

/// The Magic Eight Ball room answering `answer`, from its default camera.
int renderEightBallScreenshot(const ScreenshotOptions& options, const std::string& answer);

/// The --screenshot mode without a server: the scene named in the options.
int runScreenshot(const ScreenshotOptions& options);

}  // namespace pool::render
