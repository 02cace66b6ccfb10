// The aim scene: the rack, the aiming camera, the cue and the ghost ball from the aim prediction.
#include "client/ui/aim_screenshot.h"

#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <optional>

#include "client/app/aim_line.h"
#include "client/app/camera_rig.h"
#include "client/app/clear_area.h"
#include "client/app/controls.h"
#include "client/render/screenshot_info.h"
#include "client/ui/aim_hud.h"
#include "client/ui/scene_convert.h"
#include "game/loaded_table.h"

namespace pool::ui {

namespace {

constexpr double kDeg = std::numbers::pi / 180.0;

glm::vec3 vec(const Eigen::Vector3d& p) {
  return {static_cast<float>(p.x()), static_cast<float>(p.y()), static_cast<float>(p.z())};
}

std::vector<physics::Ball> physicsBalls(const render::Scene& scene) {
  std::vector<physics::Ball> balls;
  for (const auto& b : scene.balls) {
    balls.push_back(physics::restingBall(b.id, b.pos.head<2>(), scene.ball_radius));
  }
  return balls;
}

}  // namespace

render::CueAim cueAimOf(const app::AimState& aim, const Eigen::Vector3d& cue_ball) {
  return {
      vec(cue_ball), static_cast<float>(aim.yaw), static_cast<float>(aim.tip_side),
      static_cast<float>(aim.tip_height), static_cast<float>(aim.elevation),
      // A mouse stroke draws the cue where the mouse has it; otherwise the power bar does.
      static_cast<float>(aim.stroke_back ? *aim.stroke_back / render::kMaxDrawBack : aim.power)};
}

int runAimScreenshot(const render::ScreenshotOptions& options) {
  auto view = game::loadTable(options.table);
  if (!view) {
    std::cerr << "scene: " << view.error() << '\n';
    return 1;
  }
  auto placed_balls = render::withBalls(render::rackScene(*view), view->spec, options.aim.cue_at,
                                        options.aim.balls);
  if (!placed_balls) {
    std::cerr << placed_balls.error() << '\n';
    return 2;
  }
  render::Scene scene = std::move(*placed_balls);
  const Eigen::Vector3d cue = scene.balls.front().pos;
  const Eigen::Vector2d apex = view->context.spots.foot_spot - cue.head<2>();
  app::AimState aim;
  aim.yaw = options.aim.yaw_deg ? *options.aim.yaw_deg * kDeg : std::atan2(apex.y(), apex.x());
  aim.tip_side = options.aim.tip_side;
  aim.tip_height = options.aim.tip_height;
  aim.elevation = options.aim.elevation_deg * kDeg;
  aim.power = options.aim.power;
  const auto balls = physicsBalls(scene);
  const auto prediction = app::predictAim(cue.head<2>(), aim.yaw, balls, *view);
  const Eigen::Vector3d ghost(prediction.contact.x(), prediction.contact.y(), view->radius());
  // The eye stays above the cue's drawn line, as a player's over the cue.
  const render::CuePlacement placed =
      render::placeCue(cueAimOf(aim, cue), render::cueObstaclesOf(scene, vec(cue)));
  // What lies ahead of the ghost ball: the object ball, and the pocket it heads for.
  std::optional<Eigen::Vector3d> object, pocket;
  if (prediction.ball) {
    for (const auto& b : balls) {
      if (b.id == *prediction.ball) object = b.pos;
    }
  }
  if (prediction.pocket >= 0 && prediction.pocket < static_cast<int>(view->pockets.size())) {
    const Eigen::Vector2d m = view->pockets[static_cast<std::size_t>(prediction.pocket)].mouth;
    pocket = Eigen::Vector3d(m.x(), m.y(), view->radius());
  }

  const double aspect = static_cast<double>(options.width) / options.height;
  app::Controls controls(protocol::CommandLimits{}, app::PlacementArea{},
                         cameraRigFor(scene.geometry, aspect));
  controls.setViewport(options.width, options.height);
  controls.startTurn(cue, rules::BallInHand::None);
  controls.setYaw(aim.yaw);
  std::optional<AimHud> hud;
  app::CameraRig& rig = controls.camera();
  if (options.aim.hud) {
    // As the window does: the HUD laid out, the shot framed in the column its panes leave.
    hud.emplace(options.width, options.height, controls);
    const app::ScreenRect px = app::clearColumnFor(options.width, options.height, hud->standing());
    rig.setAimArea({px.x0 / options.width, px.y0 / options.height, px.x1 / options.width,
                    px.y1 / options.height});
    std::vector<Eigen::Vector3d> ahead;
    if (object) ahead.push_back(*object);
    if (pocket) ahead.push_back(*pocket);
    controls.setContact(ghost, ahead);
  }
  if (options.aim.camera_elevation_deg) {
    rig.raise(*options.aim.camera_elevation_deg * kDeg - rig.aimingOrbit().elevation);
  }
  rig.keepAimAbove(placed.drawn_elevation + app::kEyeOverCue);
  if (options.aim.camera_distance) {
    rig.zoom(*options.aim.camera_distance / rig.aimingOrbit().distance);
  }
  rig.settle();  // the view set up, not a glide toward it
  const render::Camera camera = cameraOf(rig.view());
  const int frames = options.frames;
  return render::renderScreenshot(
      options, scene, camera,
      [&](render::Renderer& renderer) {
        renderer.setCue(cueAimOf(aim, cue));
        renderer.setGhost(vec(ghost));
        // As the window: no shade over the cue ball, the object ball or the pocket.
        std::vector<glm::vec3> keep_clear{vec(cue)};
        if (object) keep_clear.push_back(vec(*object));
        if (pocket) keep_clear.push_back(vec(*pocket));
        renderer.setKeepClear(keep_clear);
      },
      {},
      [&](int frame) {
        if (hud) hud->draw(frame + 1 == frames);
      },
      [&](const std::string& info) {
        // The shot as the aim prediction has it, each point where the picture shows it, and
        // every pane drawn.
        auto json = nlohmann::json::parse(info);
        const auto point = [&](const Eigen::Vector3d& p) {
          return render::pointJson(camera, options.width, options.height, vec(p));
        };
        nlohmann::json shot{{"cue_ball", point(cue)}, {"ghost", point(ghost)}};
        shot["first_ball"] = prediction.ball ? nlohmann::json(*prediction.ball) : nullptr;
        if (object) shot["object_ball"] = point(*object);
        if (pocket) {
          shot["pocket"] = view->pockets[static_cast<std::size_t>(prediction.pocket)].name;
          shot["pocket_mouth"] = point(*pocket);
        }
        json["aim"] = shot;
        if (hud) json["panes"] = hud->panesJson();
        return json.dump(2);
      });
}

}  // namespace pool::ui
