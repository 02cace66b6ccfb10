// The client model's values as the renderer takes them: balls, camera, overlay segments.
#pragma once

#include <vector>

#include "client/app/camera_rig.h"
#include "client/app/overlay.h"
#include "client/render/renderer.h"
#include "client/render/scene.h"
#include "physics/ball.h"
#include "table/table_geometry.h"

namespace pool::ui {

/// Every ball as the renderer draws it (pocketed balls flagged, where the server put them).
std::vector<render::SceneBall> sceneBalls(const std::vector<physics::Ball>& balls);

render::Camera cameraOf(const app::ViewPoint& view);

/// The player's cameras for the table of `geometry` in a viewport of aspect `aspect` (w / h), the
/// aiming view told where the lamps hang so that it shows them where the shot leaves room.
app::CameraRig cameraRigFor(const table::TableGeometry& geometry, double aspect);

std::vector<render::OverlayLine> overlayLines(const std::vector<app::OverlaySegment>& segments);

}  // namespace pool::ui
