// The lines drawn over the table: the aim line to the first contact, the object ball's heading,
// and the optional direction vectors (velocity, spin) of moving balls.
#pragma once

#include <Eigen/Core>
#include <vector>

#include "client/app/aim.h"
#include "client/app/aim_line.h"
#include "client/app/bank_path.h"
#include "physics/ball.h"

namespace pool::app {

/// One coloured segment (table frame, m; colour in [0, 1]).
struct OverlaySegment {
  Eigen::Vector3d a;
  Eigen::Vector3d b;
  Eigen::Vector3d colour;
};

/// The aim line (cue ball to its first contact, then the object ball's heading) at ball-centre
/// height `radius`. The cue is drawn by the renderer (render::Renderer::setCue).
std::vector<OverlaySegment> aimOverlay(const AimPrediction& aim, double radius);

/// The bank aim aid (bank_path.h) after the aim line's first cushion, dimmer than the aim line, at
/// ball-centre height `radius`: one segment a leg.
std::vector<OverlaySegment> bankOverlay(const BankPath& path, double radius);

/// For each ball on the table that moves: its velocity (0.25 s of travel) and its spin axis
/// (length ∝ |ω|).
std::vector<OverlaySegment> motionOverlay(const std::vector<physics::Ball>& balls);

/// A ring of `radius` m round `centre` at height `z`, in `colour` (what a click would call).
std::vector<OverlaySegment> ringOverlay(const Eigen::Vector2d& centre, double radius, double z,
                                        const Eigen::Vector3d& colour);

/// The cue's direction as an arrow from the cue ball (the vector overlay while aiming).
std::vector<OverlaySegment> cueDirectionOverlay(const Eigen::Vector3d& cue_ball, double yaw);

}  // namespace pool::app
