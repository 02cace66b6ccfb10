// The part of the window no pane covers: where the overhead view frames the table.
#pragma once

#include <vector>

namespace pool::app {

/// A rectangle of the window, from its top-left corner (pixels, or fractions of the window).
struct ScreenRect {
  double x0 = 0.0;
  double y0 = 0.0;
  double x1 = 0.0;
  double y1 = 0.0;

  double width() const { return x1 - x0; }
  double height() const { return y1 - y0; }
  /// True when the two share more than an edge.
  bool overlaps(const ScreenRect& o) const {
    return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1;
  }
  bool operator==(const ScreenRect&) const = default;
};

/// How large a table of `length` × `breadth` (m, its dressing included) can be drawn in `rect`
/// (its units per metre), turned whichever way fits it larger.
double tableScale(const ScreenRect& rect, double length, double breadth);
/// Whether a `length` × `breadth` table fits `rect` larger lengthwise down the screen.
bool tableUpright(const ScreenRect& rect, double length, double breadth);

/// The rectangle of a `width` × `height` window that overlaps none of `panes` and holds the
/// largest `length` × `breadth` table (tableScale); the whole window when no pane is given. Its
/// edges are the window's and the panes'.
ScreenRect clearRectFor(double width, double height, const std::vector<ScreenRect>& panes,
                        double length, double breadth);

/// The tallest rectangle of a `width` × `height` window across its middle (x = width / 2) that
/// overlaps none of `panes`, the widest of those: where the aiming view draws the cue ball and
/// the shot ahead of it. The whole window when no pane is given.
ScreenRect clearColumnFor(double width, double height, const std::vector<ScreenRect>& panes);

}  // namespace pool::app
