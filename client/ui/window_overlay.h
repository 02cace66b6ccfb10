// The window's lines over the table: aim line, cue and motion vectors, and the cue ball in hand.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "client/app/controls.h"
#include "client/app/overlay.h"
#include "client/net/match_types.h"
#include "game/loaded_table.h"

namespace pool::ui {

/// The lines to draw this frame, and why the cue ball in hand may not go where it is (or "").
struct WindowOverlay {
  std::vector<app::OverlaySegment> lines;
  std::string placement_problem;
  std::optional<app::AimPrediction> aim;  ///< while aiming: the predicted first contact
};

/// `balls` with the cue ball at rest at `placed` (m), when set: where the player holds it in hand
/// while aiming, or where it was put for the shot sent until that shot's frames arrive.
std::vector<physics::Ball> withCueBallAt(std::vector<physics::Ball> balls,
                                         const std::optional<Eigen::Vector3d>& placed);

/// Where the cue ball in hand is held while aiming; empty when not aiming or not in hand (a shot
/// in motion draws the server's cue ball, never the placement).
std::optional<Eigen::Vector3d> heldCueBall(const app::Controls& controls);

/// The overlay over `balls` by the toggles of `controls`. While aiming at `match` (the state
/// followed, or null) it also suggests the controls a call for the predicted shot.
WindowOverlay windowOverlay(app::Controls& controls, const client::MatchView* match,
                            const std::vector<physics::Ball>& balls, const game::LoadedTable& view);

}  // namespace pool::ui
