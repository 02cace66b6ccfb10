// Offscreen rendering of a scene to a PNG file (stb_image_write) and its JSON sidecar.
#include "client/render/screenshot.h"

#include <stb_image_write.h>

#include <exception>
#include <fstream>
#include <iostream>

#include "client/render/offscreen.h"
#include "client/render/screenshot_info.h"

namespace pool::render {

namespace {

bool writePng(const std::string& path, int width, int height,
              const std::vector<std::uint8_t>& rgb) {
  return stbi_write_png(path.c_str(), width, height, 3, rgb.data(), width * 3) != 0;
}

bool writeText(const std::string& path, const std::string& text) {
  std::ofstream out(path);
  out << text;
  return static_cast<bool>(out);
}

int renderToPng(const ScreenshotOptions& options, const Scene& scene,
                const FrameHook& before_frame) {
  OffscreenContext context(options.width, options.height);
  Renderer renderer(scene);
  renderer.setOptions(options.render);
  const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
  const Camera camera = overviewCamera(scene.geometry, aspect);
  std::vector<std::uint8_t> pixels;
  for (int frame = 0; frame < options.frames; ++frame) {
    if (before_frame) before_frame(renderer, frame);
    context.bind();
    renderer.draw(camera, options.width, options.height);
    if (frame + 1 == options.frames) pixels = context.readRgb();
    context.endFrame();
  }
  if (!writePng(options.path, options.width, options.height, pixels)) {
    std::cerr << "could not write " << options.path << '\n';
    return 1;
  }
  if (!options.info_path.empty() &&
      !writeText(options.info_path, screenshotInfoJson(camera, options.width, options.height,
                                                       scene.ball_radius, renderer.drawnBalls()))) {
    std::cerr << "could not write " << options.info_path << '\n';
    return 1;
  }
  return 0;
}

}  // namespace

int renderScreenshot(const ScreenshotOptions& options, const Scene& scene,
                     const FrameHook& before_frame) {
  if (options.frames < 1) {
    std::cerr << "--frames must be at least 1\n";
    return 2;
  }
  try {
    return renderToPng(options, scene, before_frame);
  } catch (const std::exception& e) {
    std::cerr << "render: " << e.what() << '\n';
    return 1;
  }
}

int runScreenshot(const ScreenshotOptions& options) {
  if (options.scene != "rack") {
    std::cerr << "unknown scene '" << options.scene << "' (known: rack, eightball)\n";
    return 2;
  }
  auto scene = rackScene();
  if (!scene) {
    std::cerr << "scene: " << scene.error() << '\n';
    return 1;
  }
  return renderScreenshot(options, *scene);
}

}  // namespace pool::render
