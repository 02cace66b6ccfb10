// Test helpers for the client's controls model: a 9-ft table's controls, the camera as the
// renderer sees it, and the command a shot would put on the wire checked by the server's validator.
#pragma once

#include <gtest/gtest.h>

#include <glm/glm.hpp>

#include "client/app/controls.h"
#include "client/render/renderer.h"
#include "game/loaded_table.h"
#include "net/convert.h"
#include "net/shot_command_check.h"

namespace pool::app::test {

inline constexpr double kRadius = 0.028575;

/// The wpa-9ft table as the client loads it, once per test program.
inline const game::LoadedTable& nineFoot() {
  static const game::LoadedTable view = [] {
    auto loaded = game::loadTable("wpa-9ft");
    if (!loaded) throw std::runtime_error(loaded.error());
    return std::move(*loaded);
  }();
  return view;
}

/// Controls of a 9-ft table in a 1280 × 720 viewport.
inline Controls nineFootControls() {
  Controls controls(protocol::CommandLimits{}, PlacementArea{},
                    CameraRig(2.54, 1.27, 1280.0 / 720.0));
  controls.setViewport(1280, 720);
  return controls;
}

/// The renderer's camera for a view point.
inline render::Camera cameraOf(const ViewPoint& view) {
  auto v = [](const Eigen::Vector3d& p) {
    return glm::vec3(static_cast<float>(p.x()), static_cast<float>(p.y()),
                     static_cast<float>(p.z()));
  };
  return {v(view.eye), v(view.target), static_cast<float>(view.fov_y_deg)};
}

/// The server's field check of `request` once on the wire (with a match and seat filled in).
inline net::CommandCheck wireCheck(protocol::ShotRequest request) {
  request.match = "srv-1";
  request.seat = 0;
  const auto sample = net::toWire(request);
  return net::validateShotCommand(*sample);
}

/// Holds `key` (with `mods`) for `seconds`, in 60 Hz steps.
inline void hold(Controls& controls, Key key, double seconds, Mods mods = {}) {
  controls.keyDown(key, mods);
  const int steps = static_cast<int>(std::lround(seconds * 60.0));
  for (int i = 0; i < steps; ++i) controls.advance(1.0 / 60.0);
  controls.keyUp(key);
}

/// The cue's turn from one press of an aiming arrow held `seconds`: the press's step, then the
/// held rate past the repeat delay (ControlRates' documented rule).
inline double heldTurn(double seconds, bool fine = false, const ControlRates& r = {}) {
  return (fine ? r.fine_yaw_step : r.yaw_step) +
         (fine ? r.fine_yaw : r.yaw) * std::max(0.0, seconds - r.repeat_delay);
}

/// Charges for `seconds` and releases: the shot sent.
inline std::optional<protocol::ShotRequest> shoot(Controls& controls, double seconds) {
  hold(controls, Key::Space, seconds);
  return controls.takeShot();
}

}  // namespace pool::app::test
