// The window's largest pane-free rectangle for a table.
#include "client/app/clear_area.h"

#include <algorithm>

namespace pool::app {

double tableScale(const ScreenRect& rect, double length, double breadth) {
  const double across = std::min(rect.width() / length, rect.height() / breadth);
  const double upright = std::min(rect.width() / breadth, rect.height() / length);
  return std::max(across, upright);
}

bool tableUpright(const ScreenRect& rect, double length, double breadth) {
  const double across = std::min(rect.width() / length, rect.height() / breadth);
  const double upright = std::min(rect.width() / breadth, rect.height() / length);
  return upright > across;
}

namespace {

/// The rectangle with edges at the window's and the panes' that overlaps no pane and scores
/// highest by `score` (every candidate: a handful of panes give a few thousand, each checked
/// against every pane); scores below 0 never win.
template <class Score>
ScreenRect bestClear(double width, double height, const std::vector<ScreenRect>& panes,
                     Score score) {
  std::vector<double> xs{0.0, width}, ys{0.0, height};
  for (const ScreenRect& p : panes) {
    for (double x : {p.x0, p.x1}) xs.push_back(std::clamp(x, 0.0, width));
    for (double y : {p.y0, p.y1}) ys.push_back(std::clamp(y, 0.0, height));
  }
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  ScreenRect best{0.0, 0.0, width, height};
  double best_score = -1.0;
  for (std::size_t a = 0; a < xs.size(); ++a) {
    for (std::size_t b = a + 1; b < xs.size(); ++b) {
      for (std::size_t c = 0; c < ys.size(); ++c) {
        for (std::size_t d = c + 1; d < ys.size(); ++d) {
          const ScreenRect r{xs[a], ys[c], xs[b], ys[d]};
          const double value = score(r);
          if (value <= best_score) continue;
          if (std::any_of(panes.begin(), panes.end(),
                          [&](const ScreenRect& p) { return r.overlaps(p); })) {
            continue;
          }
          best = r;
          best_score = value;
        }
      }
    }
  }
  return best;
}

}  // namespace

ScreenRect clearRectFor(double width, double height, const std::vector<ScreenRect>& panes,
                        double length, double breadth) {
  return bestClear(width, height, panes,
                   [&](const ScreenRect& r) { return tableScale(r, length, breadth); });
}

ScreenRect clearColumnFor(double width, double height, const std::vector<ScreenRect>& panes) {
  const double middle = width / 2;
  return bestClear(width, height, panes, [&](const ScreenRect& r) {
    if (r.x0 > middle || r.x1 < middle) return -1.0;
    return r.height() * (width + 1.0) + r.width();  // the tallest, then the widest
  });
}

}  // namespace pool::app
