// Where the HUD's standing panes lie on the window, for the overhead view to frame the table
// clear of them.
#pragma once

#include <vector>

#include "client/app/clear_area.h"

namespace pool::ui {

/// The rectangles (pixels from the top-left corner) of the HUD's panes that stay up while a
/// match is played (Match, Last shot, Shot, Match log), as Dear ImGui laid them out this frame;
/// questions and the help come and go, and are left out.
std::vector<app::ScreenRect> standingPaneRects();

/// The part of the window those panes leave clear for a `length` × `breadth` table (m), as
/// fractions of the window (app::clearRectFor).
app::ScreenRect clearFraction(double length, double breadth);

/// The column down the window's middle those panes leave clear for the aiming view, as fractions
/// of the window (app::clearColumnFor).
app::ScreenRect clearColumnFraction();

}  // namespace pool::ui
