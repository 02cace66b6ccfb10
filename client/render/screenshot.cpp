// Offscreen rendering of a scene to a PNG file (stb_image_write) and its JSON sidecar.
#include "client/render/screenshot.h"

#include <stb_image_write.h>

#include <exception>
#include <fstream>
#include <functional>
#include <iostream>
#include <memory>

#include "client/render/eight_ball_room.h"
#include "client/render/offscreen.h"
#include "client/render/screenshot_info.h"
#include "client/room/magic_eight_ball.h"

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

/// What one screenshot draws, made once its context is current.
struct FrameSource {
  std::function<void(int frame)> draw;
  std::function<std::string()> info;  ///< the sidecar's text; may be empty
};

int renderFrames(const ScreenshotOptions& options, const std::function<FrameSource()>& make) {
  OffscreenContext context(options.width, options.height);
  const FrameSource source = make();
  std::vector<std::uint8_t> pixels;
  for (int frame = 0; frame < options.frames; ++frame) {
    context.bind();
    source.draw(frame);
    if (frame + 1 == options.frames) pixels = context.readRgb();
    context.endFrame();
  }
  if (!writePng(options.path, options.width, options.height, pixels)) {
    std::cerr << "could not write " << options.path << '\n';
    return 1;
  }
  if (!options.info_path.empty() && source.info && !writeText(options.info_path, source.info())) {
    std::cerr << "could not write " << options.info_path << '\n';
    return 1;
  }
  return 0;
}

/// Checks the options, then renders with the error handling every screenshot shares.
int guarded(const ScreenshotOptions& options, const std::function<FrameSource()>& make) {
  if (options.frames < 1) {
    std::cerr << "--frames must be at least 1\n";
    return 2;
  }
  try {
    return renderFrames(options, make);
  } catch (const std::exception& e) {
    std::cerr << "render: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace

int renderScreenshot(const ScreenshotOptions& options, const Scene& scene, const Camera& camera,
                     const SceneSetup& setup, const FrameHook& before_frame,
                     const FrameOverlay& after_draw, const InfoAmend& amend) {
  std::shared_ptr<Renderer> renderer;
  return guarded(options, [&] {
    renderer = std::make_shared<Renderer>(scene);
    renderer->setOptions(options.render);
    if (setup) setup(*renderer);
    return FrameSource{[&](int frame) {
                         if (before_frame) before_frame(*renderer, frame);
                         renderer->draw(camera, options.width, options.height);
                         if (after_draw) after_draw(frame);
                       },
                       [&] {
                         const std::string info =
                             screenshotInfoJson(camera, options.width, options.height, *renderer,
                                                scene.ball_radius, scene.geometry);
                         return amend ? amend(info) : info;
                       }};
  });
}

int renderScreenshot(const ScreenshotOptions& options, const Scene& scene,
                     const FrameHook& before_frame) {
  const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
  return renderScreenshot(options, scene, overviewCamera(scene.geometry, aspect), {}, before_frame);
}

Scene spreadScene(const game::LoadedTable& table) {
  Scene scene = tableScene(table);
  const double r = scene.ball_radius;
  // Between and beside the lamps (over x = ±L/4), none straight under one; the last against the
  // +y cushion, a little toward the middle from the head lamp (it darkens the cushion).
  const double against = scene.geometry.width / 2 - r;
  const double spots[][2] = {{0.0, 0.0},     {-0.3, 0.3}, {0.35, -0.3},
                             {-0.95, -0.35}, {1.0, 0.4},  {-0.45, against}};
  int id = 0;
  for (const auto& spot : spots) {
    scene.balls.push_back({id, Eigen::Vector3d(spot[0], spot[1], r), numberTowardViewer()});
    id = id == 0 ? 2 : id + 2;
  }
  return scene;
}

Result<Scene> spreadScene(const std::string& table) {
  auto loaded = game::loadTable(table);
  if (!loaded) return Result<Scene>::fail(loaded.error());
  return Result<Scene>::ok(spreadScene(*loaded));
}

int renderEightBallScreenshot(const ScreenshotOptions& options, const std::string& answer) {
  std::shared_ptr<EightBallRoom> room;
  const Camera camera = EightBallRoom::defaultCamera();
  return guarded(options, [&] {
    room = std::make_shared<EightBallRoom>();
    room->setOptions(options.render);
    return FrameSource{[&](int) { room->draw(camera, options.width, options.height, answer); },
                       [&] {
                         return eightBallInfoJson(camera, options.width, options.height,
                                                  EightBallRoom::ballCentre(),
                                                  EightBallRoom::ballRadius(),
                                                  EightBallRoom::windowCentre(camera), answer);
                       }};
  });
}

int runScreenshot(const ScreenshotOptions& options) {
  if (options.scene == "eightball") {
    const auto reply = pool::room::answer(options.question, options.seed);
    if (!reply) {
      std::cerr << reply.error() << '\n';
      return 2;
    }
    return renderEightBallScreenshot(options, *reply);
  }
  if (options.scene != "rack" && options.scene != "top") {
    std::cerr << "unknown scene '" << options.scene << "' (known: rack, top, aim, eightball)\n";
    return 2;
  }
  auto loaded = game::loadTable(options.table);
  if (!loaded) {
    std::cerr << "scene: " << loaded.error() << '\n';
    return 1;
  }
  auto scene = withBalls(options.scene == "top" ? spreadScene(*loaded) : rackScene(*loaded),
                         loaded->spec, options.aim.cue_at, options.aim.balls);
  if (!scene) {
    std::cerr << scene.error() << '\n';
    return 2;
  }
  if (options.scene == "top") {
    const float aspect = static_cast<float>(options.width) / static_cast<float>(options.height);
    return renderScreenshot(options, *scene, topCamera(scene->geometry, aspect), {});
  }
  return renderScreenshot(options, *scene);
}

}  // namespace pool::render
