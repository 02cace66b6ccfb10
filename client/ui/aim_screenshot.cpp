// The aim scene: the rack, the aiming camera, the cue and the ghost ball from the aim prediction.
#include "client/ui/aim_screenshot.h"

#include <cmath>
#include <iostream>
#include <numbers>

#include "client/app/aim_line.h"
#include "client/app/camera_rig.h"
#include "client/bot/ai/table_view.h"
#include "client/ui/scene_convert.h"

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
  auto view = bot::loadTableView("wpa-9ft");
  auto scene = render::rackScene("wpa-9ft");
  if (!view || !scene) {
    std::cerr << "scene: " << (view ? scene.error() : view.error()) << '\n';
    return 1;
  }
  if (options.aim.cue_at.size() == 2) {
    scene->balls.front().pos.head<2>() =
        Eigen::Vector2d(options.aim.cue_at[0], options.aim.cue_at[1]);
  }
  const Eigen::Vector3d cue = scene->balls.front().pos;
  const Eigen::Vector2d apex = view->context.spots.foot_spot - cue.head<2>();
  app::AimState aim;
  aim.yaw = options.aim.yaw_deg ? *options.aim.yaw_deg * kDeg : std::atan2(apex.y(), apex.x());
  aim.tip_side = options.aim.tip_side;
  aim.tip_height = options.aim.tip_height;
  aim.elevation = options.aim.elevation_deg * kDeg;
  aim.power = options.aim.power;
  const auto prediction = app::predictAim(cue.head<2>(), aim.yaw, physicsBalls(*scene), *view);

  const double aspect = static_cast<double>(options.width) / options.height;
  app::CameraRig rig(view->spec.length, view->spec.width, aspect);
  rig.setAiming(true);
  rig.followCue(cue, aim.yaw);
  // The eye stays above the cue's drawn line, as a player's over the cue.
  const render::CuePlacement placed =
      render::placeCue(cueAimOf(aim, cue), render::cueObstaclesOf(*scene, vec(cue)));
  if (options.aim.camera_elevation_deg) {
    rig.raise(*options.aim.camera_elevation_deg * kDeg - rig.aimingOrbit().elevation);
  }
  rig.keepAimAbove(placed.drawn_elevation + app::kEyeOverCue);
  if (options.aim.camera_distance) {
    rig.zoom(*options.aim.camera_distance / rig.aimingOrbit().distance);
  }
  rig.settle();  // the view set up, not a glide toward it
  const Eigen::Vector3d ghost(prediction.contact.x(), prediction.contact.y(), view->radius());
  return render::renderScreenshot(options, *scene, cameraOf(rig.view()),
                                  [&](render::Renderer& renderer) {
                                    renderer.setCue(cueAimOf(aim, cue));
                                    renderer.setGhost(vec(ghost));
                                  });
}

}  // namespace pool::ui
