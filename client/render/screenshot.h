// The --screenshot mode: render a scene offscreen for a few frames and write the last as PNG,
// optionally with a JSON sidecar of the camera and the balls as drawn.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "client/render/renderer.h"

namespace pool::render {

/// The shot drawn in the aim scene (angles in degrees, tip in fractions of R).
struct AimOptions {
  std::optional<double> yaw_deg;  ///< cue heading, 0 = +x; default: at the rack's apex ball
  double tip_side = 0.0;          ///< right of centre, seen from behind
  double tip_height = 0.0;        ///< above centre
  double elevation_deg = 0.0;     ///< the cue above horizontal
  double power = 0.0;             ///< 0–1: the cue drawn back
  std::optional<double> camera_elevation_deg;  ///< the aiming view raised to this; default: eye
  std::optional<double> camera_distance;       ///< the aiming view this far from the cue ball, m
  std::vector<double> cue_at;                  ///< x, y of the cue ball (m); empty: the scene's
  /// ID X Y of each object ball (m), instead of the scene's (rack, aim and top); empty: those.
  std::vector<double> balls;
  bool hud = false;  ///< drawn with the window's HUD as a player sees it (and the view framed)
};

/// What to render and where to write it.
struct ScreenshotOptions {
  std::string path;               ///< PNG file to write
  std::string info_path;          ///< JSON sidecar (camera, image size, balls drawn); empty: none
  int frames = 3;                 ///< frames to render; the last one is written
  std::string scene = "rack";     ///< rack, aim, top or eightball (ignored when spectating)
  std::string table = "wpa-9ft";  ///< the table spec of the rack, aim and top scenes
  std::string question = "Will I win?";  ///< asked in the eightball scene
  std::uint64_t seed = 0;                ///< the Magic Eight Ball's seed
  AimOptions aim;                        ///< the aim scene's shot
  RenderOptions render;                  ///< wireframe, textures, lighting
  int width = 1280;
  int height = 720;
};

/// Called before each frame (0-based) to bring the renderer's balls up to date.
using FrameHook = std::function<void(Renderer& renderer, int frame)>;

/// Called once on the new renderer, before the first frame (cue, ghost ball).
using SceneSetup = std::function<void(Renderer& renderer)>;

/// Drawn over each frame (0-based) after the scene, in its context (the window's HUD).
using FrameOverlay = std::function<void(int frame)>;

/// Given the sidecar's text, returns it with more in it.
using InfoAmend = std::function<std::string(const std::string& info)>;

/// Renders `scene` from `camera` and writes the PNG (and the sidecar). Returns the process exit
/// code (0 on success); errors go to stderr as one line.
int renderScreenshot(const ScreenshotOptions& options, const Scene& scene, const Camera& camera,
                     const SceneSetup& setup, const FrameHook& before_frame = {},
                     const FrameOverlay& after_draw = {}, const InfoAmend& amend = {});

/// The same from the overview camera.
int renderScreenshot(const ScreenshotOptions& options, const Scene& scene,
                     const FrameHook& before_frame = {});

/// A few balls spread over the table, apart from each other and from under the lamps (the top
/// scene: their shadows fall clear of them), and one against the +y cushion near the head lamp.
Scene spreadScene(const game::LoadedTable& table);
/// As above, of the table named `table`.
Result<Scene> spreadScene(const std::string& table = "wpa-9ft");

/// The Magic Eight Ball room answering `answer`, from its default camera.
int renderEightBallScreenshot(const ScreenshotOptions& options, const std::string& answer);

/// The --screenshot mode without a server: the scene named in the options (rack or top on
/// options.table, with --cue-at and --balls; eightball; the aim scene needs the client's aiming
/// model and is run by pool::ui).
int runScreenshot(const ScreenshotOptions& options);

}  // namespace pool::render
