// Orbit cameras and pixel rays.
#include "client/app/camera_rig.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>

namespace pool::app {
namespace {

constexpr double kAimElevation = 0.22;  // rad: a player's eye a little above the cue
constexpr double kAimDistance = 0.75;   // m behind the cue ball
constexpr double kMargin = 0.25;        // m of floor shown beyond the table's ends

double radians(double degrees) {
  return degrees * std::numbers::pi / 180.0;
}

/// A part of the window in normalised device coordinates (y up).
struct NdcBox {
  double left, right, bottom, top;
};

/// How far to raise the look-at point (m; `view_at` gives the view for a height) so that a light
/// of `lights` ahead of the eye is drawn inside `box` (its top edge less a little, for the shade
/// hanging round it) while every point of `points` stays inside it; 0 when no light fits so or
/// none needs raising. Raising the look-at point lowers everything on the screen, monotonically.
double lightRoom(const std::function<ViewPoint(double)>& view_at, double aspect,
                 const std::vector<Eigen::Vector3d>& points,
                 const std::vector<Eigen::Vector3d>& lights, const NdcBox& box) {
  constexpr double kHighest = 2.0;   // m above the cue ball: far past level for any eye
  constexpr double kBelowTop = 0.1;  // NDC: the light this far inside the top edge
  // Whether every point of the shot is inside the box (raising the look-at point moves them down
  // and, those below the middle, out toward the sides).
  const auto framed = [&](double up) {
    const ViewPoint v = view_at(up);
    return std::all_of(points.begin(), points.end(), [&](const Eigen::Vector3d& p) {
      const auto n = ndcOf(v, aspect, p);
      return n && n->x() >= box.left && n->x() <= box.right && n->y() >= box.bottom &&
             n->y() <= box.top;
    });
  };
  // The most the shot allows: a point on the box's edge.
  if (!framed(0.0)) return 0.0;
  double lo = 0.0, hi = kHighest;
  if (framed(hi)) lo = hi;
  for (int i = 0; i < 40 && hi > lo; ++i) {
    const double mid = (lo + hi) / 2;
    (framed(mid) ? lo : hi) = mid;
  }
  const double most = lo;
  double best = 0.0;
  bool found = false;
  for (const auto& light : lights) {
    const auto at = [&](double up) { return ndcOf(view_at(up), aspect, light); };
    const auto now = at(0.0);
    if (!now) continue;  // behind the eye
    if (now->y() <= box.top - kBelowTop && now->x() >= box.left && now->x() <= box.right) {
      return 0.0;  // already in view
    }
    const auto raised = at(most);
    if (!raised || raised->y() > box.top - kBelowTop) continue;  // cannot be brought in
    double a = 0.0, b = most;
    for (int i = 0; i < 40; ++i) {
      const double mid = (a + b) / 2;
      const auto n = at(mid);
      (n && n->y() <= box.top - kBelowTop ? b : a) = mid;
    }
    const auto shown = at(b);
    if (!shown || shown->x() < box.left || shown->x() > box.right) continue;
    if (!found || b < best) best = b;
    found = true;
  }
  return found ? best : 0.0;
}

}  // namespace

ViewPoint blend(const ViewPoint& from, const ViewPoint& to, double s) {
  s = std::clamp(s, 0.0, 1.0);
  const double e = s * s * (3.0 - 2.0 * s);
  return {from.eye + e * (to.eye - from.eye), from.target + e * (to.target - from.target),
          from.fov_y_deg + e * (to.fov_y_deg - from.fov_y_deg)};
}

ViewPoint Orbit::view(double fov_y_deg) const {
  const Eigen::Vector3d dir(std::cos(elevation) * std::cos(azimuth),
                            std::cos(elevation) * std::sin(azimuth), std::sin(elevation));
  return {target + distance * dir, target, fov_y_deg};
}

CameraRig::CameraRig(double table_length, double table_width, double aspect)
    : table_length_(table_length), table_width_(table_width), aspect_(aspect) {
  resetOverview();
  aim_.elevation = kAimElevation;
  aim_.distance = kAimDistance;
}

void CameraRig::resetOverview() {
  // From the long side (-y), high enough that the whole length fits the horizontal field of view
  // and the whole width the vertical one.
  watch_.target = Eigen::Vector3d(0.0, 0.0, -0.05);
  watch_.azimuth = -std::numbers::pi / 2;
  watch_.elevation = std::atan2(1.0, 0.55);
  const double half_fov_y = radians(fov_y_deg_) / 2;
  const double half_fov_x = std::atan(std::tan(half_fov_y) * aspect_);
  const double along = (table_length_ / 2 + kMargin) / std::tan(half_fov_x);
  const double across = (table_width_ / 2 + kMargin) / std::tan(half_fov_y);
  watch_.distance =
      std::clamp(std::max(along, across) * 1.15, limits_.min_distance, limits_.max_distance);
}

void CameraRig::setAiming(bool aiming) {
  if (aiming == aiming_) return;
  startGlide();
  aiming_ = aiming;
}

void CameraRig::behindCue() {
  startGlide();
  aim_turn_ = 0.0;
  look_ = Eigen::Vector2d::Zero();
  framed_.reset();
  aim_.elevation = kAimElevation;
  aim_.distance = kAimDistance;
  look_up_ = 0.0;
  overhead_ = false;
}

void CameraRig::frameAim(const Eigen::Vector3d& cue, const Eigen::Vector3d& contact,
                         double ball_radius) {
  constexpr double kHighest = 0.8;  // rad: beyond this the view is no longer a player's
  constexpr double kGap = 0.01;     // rad of clear felt between the two balls as seen
  Orbit probe = aim_;
  probe.target = cue;
  for (double e = aim_.elevation; e <= kHighest; e += 0.005) {
    probe.elevation = e;
    const Eigen::Vector3d eye = probe.view(fov_y_deg_).eye;
    const Eigen::Vector3d to_cue = cue - eye, to_contact = contact - eye;
    const double apart =
        std::acos(std::clamp(to_cue.normalized().dot(to_contact.normalized()), -1.0, 1.0));
    const double sizes = std::asin(std::min(1.0, ball_radius / to_cue.norm())) +
                         std::asin(std::min(1.0, ball_radius / to_contact.norm()));
    if (apart >= sizes + kGap) {
      aim_.elevation = std::clamp(e, limits_.min_elevation, limits_.max_elevation);
      return;
    }
  }
  aim_.elevation = std::clamp(kHighest, limits_.min_elevation, limits_.max_elevation);
}

void CameraRig::setOverhead(bool overhead) {
  if (overhead == overhead_) return;
  startGlide();
  overhead_ = overhead;
  overhead_zoom_ = 1.0;
  overhead_pan_ = Eigen::Vector2d::Zero();
}

void CameraRig::setClearArea(const ScreenRect& fraction) {
  const ScreenRect f{std::clamp(fraction.x0, 0.0, 1.0), std::clamp(fraction.y0, 0.0, 1.0),
                     std::clamp(fraction.x1, 0.0, 1.0), std::clamp(fraction.y1, 0.0, 1.0)};
  if (!(f.width() > 0.05 && f.height() > 0.05)) return;  // no room: keep the last
  const double moved = std::max({std::abs(f.x0 - clear_.x0), std::abs(f.y0 - clear_.y0),
                                 std::abs(f.x1 - clear_.x1), std::abs(f.y1 - clear_.y1)});
  if (moved <= 0.01) return;
  if (overhead_) startGlide();
  clear_ = f;
}

void CameraRig::hold(bool held) {
  if (held && !held_) {
    held_ = view();
    glide_.reset();
  } else if (!held && held_) {
    glide_ = Glide{*held_, 0.0};
    held_.reset();
  }
}

void CameraRig::startGlide() {
  if (held_) return;
  glide_ = Glide{view(), 0.0};
}

void CameraRig::update(double dt) {
  if (!(dt > 0)) return;
  if (chase_ && !aiming_ && !overhead_) {
    watch_.target += (*chase_ - watch_.target) * (1.0 - std::exp(-3.0 * dt));
  }
  if (!glide_) return;
  glide_->t += dt;
  if (glide_->t >= kGlideTime) glide_.reset();
}

Orbit CameraRig::overheadOrbit() const {
  // Straight down (as near as an orbit with +z up allows), the table as large as the clear area
  // holds it: lengthwise across (the eye on the -y side) or up the screen (on the -x side, the
  // head end at the bottom), whichever is larger, its centre at the area's centre.
  const double length = table_length_ + 2 * kOverheadMargin;
  const double breadth = table_width_ + 2 * kOverheadMargin;
  // At distance d the target's plane shows 2 d tan(fov_y / 2) of height and aspect times that of
  // width; the area is a fraction of each.
  const double t = std::tan(radians(fov_y_deg_) / 2);
  const double per_width = clear_.width() * 2 * t * aspect_;  // m of the area's width per m of d
  const double per_height = clear_.height() * 2 * t;
  const bool upright = tableUpright({0.0, 0.0, per_width, per_height}, length, breadth);
  const double across = upright ? breadth : length;
  const double down = upright ? length : breadth;
  Orbit o;
  o.azimuth = upright ? std::numbers::pi : -std::numbers::pi / 2;
  o.elevation = limits_.max_elevation;
  // 4 % more: the view leans 1.2° off vertical and the balls stand above the slate.
  o.distance = std::clamp(std::max(across / per_width, down / per_height) * 1.04 * overhead_zoom_,
                          limits_.min_distance, limits_.max_distance);
  // The screen's up and right on the table; the table's centre moved from the screen's centre to
  // the area's, then the pan.
  const Eigen::Vector2d up(-std::cos(o.azimuth), -std::sin(o.azimuth));
  const Eigen::Vector2d right(up.y(), -up.x());
  const double half_h = o.distance * t, half_w = half_h * aspect_;
  const double cx = clear_.x0 + clear_.x1 - 1.0, cy = 1.0 - (clear_.y0 + clear_.y1);
  const Eigen::Vector2d target = -cx * half_w * right - cy * half_h * up + overhead_pan_;
  o.target = Eigen::Vector3d(target.x(), target.y(), 0.0);
  return o;
}

void CameraRig::setAspect(double aspect) {
  if (!(aspect > 0) || aspect == aspect_) return;
  aspect_ = aspect;
  resetOverview();
}

void CameraRig::followCue(const Eigen::Vector3d& cue_ball, double yaw) {
  aim_.target = cue_ball;
  aim_.azimuth = yaw + std::numbers::pi + aim_turn_;
}

void CameraRig::orbit(double d_azimuth) {
  if (overhead_) {
    panOverhead(d_azimuth, 0.0);
    return;
  }
  if (aiming_) {
    aim_turn_ = std::remainder(aim_turn_ + d_azimuth, 2 * std::numbers::pi);
    aim_.azimuth += d_azimuth;
    return;
  }
  watch_.azimuth = std::remainder(watch_.azimuth + d_azimuth, 2 * std::numbers::pi);
}

void CameraRig::raise(double d_elevation) {
  if (overhead_) {
    panOverhead(0.0, d_elevation);
    return;
  }
  Orbit& o = active();
  o.elevation = std::clamp(o.elevation + d_elevation, limits_.min_elevation, limits_.max_elevation);
}

void CameraRig::keepAimAbove(double elevation) {
  const double before = aim_.elevation;
  aim_.elevation = std::clamp(std::max(aim_.elevation, std::min(elevation, kHighestAimEye)),
                              limits_.min_elevation, limits_.max_elevation);
  // A raised eye sees the framed shot lower on the screen: frame it again from there.
  if (aim_.elevation > before + 1e-9 && framed_) {
    const auto [cue, ahead] = *framed_;
    frameShot(cue, ahead);
  }
}

void CameraRig::panOverhead(double right, double up) {
  // In the screen's directions: + moves the view right and up (the table the other way), so a
  // drag (orbit by -dx, raise by +dy) carries the table with the cursor.
  const Orbit o = overheadOrbit();
  const Eigen::Vector2d screen_up(-std::cos(o.azimuth), -std::sin(o.azimuth));
  const Eigen::Vector2d screen_right(screen_up.y(), -screen_up.x());
  const double scale = kOverheadPan * o.distance;
  overhead_pan_ += scale * (right * screen_right + up * screen_up);
  // Never so far that the table leaves the view: its centre stays within its own half length.
  overhead_pan_ = overhead_pan_.cwiseMax(Eigen::Vector2d(-table_length_ / 2, -table_width_ / 2))
                      .cwiseMin(Eigen::Vector2d(table_length_ / 2, table_width_ / 2));
}

void CameraRig::zoom(double factor) {
  if (!(factor > 0)) return;
  if (overhead_) {
    overhead_zoom_ = std::clamp(overhead_zoom_ * factor, 0.2, 1.5);
    return;
  }
  Orbit& o = active();
  o.distance = std::clamp(o.distance * factor, limits_.min_distance, limits_.max_distance);
}

ViewPoint CameraRig::goal() const {
  if (overhead_) return overheadOrbit().view(fov_y_deg_);
  if (!aiming_) return watch_.view(fov_y_deg_);
  return aimView(aim_, look_, look_up_);
}

ViewPoint CameraRig::aimView(const Orbit& orbit, const Eigen::Vector2d& look, double up) const {
  // The eye where the orbit has it; the look-at point look.x() m on from the cue ball (away from
  // the eye), look.y() m to the left of that line and `up` m above it.
  ViewPoint v = orbit.view(kAimFovDeg);
  const Eigen::Vector3d on(-std::cos(orbit.azimuth), -std::sin(orbit.azimuth), 0.0);
  const Eigen::Vector3d left(-on.y(), on.x(), 0.0);
  v.target += look.x() * on + look.y() * left + Eigen::Vector3d(0.0, 0.0, up);
  return v;
}

void CameraRig::frameShot(const Eigen::Vector3d& cue, const std::vector<Eigen::Vector3d>& ahead) {
  constexpr double kEdge = 0.06;     // NDC kept clear inside the area's edges
  constexpr double kFarthest = 3.0;  // m: the aiming view draws back no further
  framed_ = std::make_pair(cue, ahead);
  std::vector<Eigen::Vector3d> points{cue};
  points.insert(points.end(), ahead.begin(), ahead.end());
  const double left = 2 * aim_area_.x0 - 1 + kEdge, right = 2 * aim_area_.x1 - 1 - kEdge;
  const double bottom = 1 - 2 * aim_area_.y1 + kEdge, top = 1 - 2 * aim_area_.y0 - kEdge;
  if (!(right > left && top > bottom)) return;
  Orbit probe = aim_;
  probe.target = cue;
  double reach = 0.0;  // the farthest point's distance from the cue ball, m
  for (const auto& p : points) reach = std::max(reach, (p - cue).head<2>().norm());
  // The points' extent on screen (NDC) for a look offset, and whether all are in the area.
  struct Extent {
    Eigen::Vector2d low{1e9, 1e9}, high{-1e9, -1e9};
    bool fits = true;
  };
  const auto extent = [&](const Eigen::Vector2d& look) {
    Extent out;
    const ViewPoint v = aimView(probe, look);
    for (const auto& p : points) {
      const auto n = ndcOf(v, aspect_, p);
      if (!n) {
        out.fits = false;
        continue;
      }
      out.low = out.low.cwiseMin(*n);
      out.high = out.high.cwiseMax(*n);
    }
    out.fits = out.fits && out.low.x() >= left && out.high.x() <= right && out.low.y() >= bottom &&
               out.high.y() <= top;
    return out;
  };
  // Bisects the look offset's component `axis` for the extent centred on the area along `screen`
  // (looking further ahead lowers every point; further left moves every point right).
  const auto centre = [&](Eigen::Vector2d look, int axis, int screen, double lo, double hi) {
    const double middle = screen == 0 ? (left + right) / 2 : (bottom + top) / 2;
    for (int i = 0; i < 40; ++i) {
      look[axis] = (lo + hi) / 2;
      const Extent e = extent(look);
      const bool past = e.high[screen] + e.low[screen] > 2 * middle;
      // Ahead (y on screen): past the middle → look further. Left (x): past → look less left.
      if (screen == 1) {
        (past ? lo : hi) = look[axis];
      } else {
        (past ? hi : lo) = look[axis];
      }
    }
    look[axis] = (lo + hi) / 2;
    return look;
  };
  for (int attempt = 0; attempt < 16; ++attempt) {
    Eigen::Vector2d look = Eigen::Vector2d::Zero();
    for (int pass = 0; pass < 2; ++pass) {
      look = centre(look, 0, 1, -0.5, reach + 1.0);
      look = centre(look, 1, 0, -reach - 1.0, reach + 1.0);
    }
    if (extent(look).fits) {
      aim_.distance = probe.distance;
      look_ = look;
      look_up_ = lightRoom([&](double up) { return aimView(probe, look, up); }, aspect_, points,
                           lights_, {left, right, bottom, top});
      return;
    }
    if (probe.distance >= kFarthest) break;
    probe.distance = std::min(probe.distance * 1.12, kFarthest);
  }
}

ViewPoint CameraRig::view() const {
  if (held_) return *held_;
  if (glide_) return blend(glide_->from, goal(), glide_->t / kGlideTime);
  return goal();
}

std::optional<Eigen::Vector2d> ndcOf(const ViewPoint& view, double aspect,
                                     const Eigen::Vector3d& p) {
  const Eigen::Vector3d forward = (view.target - view.eye).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const Eigen::Vector3d d = p - view.eye;
  const double depth = d.dot(forward);
  if (!(depth > 1e-6)) return std::nullopt;
  const double tan_y = std::tan(radians(view.fov_y_deg) / 2);
  return Eigen::Vector2d(d.dot(right) / (depth * tan_y * aspect), d.dot(up) / (depth * tan_y));
}

std::optional<Eigen::Vector2d> pointUnderPixel(const ViewPoint& view, int width, int height,
                                               double px, double py, double plane_z) {
  if (width <= 0 || height <= 0) return std::nullopt;
  const Eigen::Vector3d forward = (view.target - view.eye).normalized();
  const Eigen::Vector3d right = forward.cross(Eigen::Vector3d::UnitZ()).normalized();
  const Eigen::Vector3d up = right.cross(forward);
  const double tan_y = std::tan(radians(view.fov_y_deg) / 2);
  const double aspect = static_cast<double>(width) / height;
  const double ndc_x = 2.0 * px / width - 1.0;
  const double ndc_y = 1.0 - 2.0 * py / height;
  const Eigen::Vector3d dir = forward + ndc_x * tan_y * aspect * right + ndc_y * tan_y * up;
  if (std::abs(dir.z()) < 1e-12) return std::nullopt;
  const double t = (plane_z - view.eye.z()) / dir.z();
  if (t <= 0) return std::nullopt;
  const Eigen::Vector3d hit = view.eye + t * dir;
  return Eigen::Vector2d(hit.x(), hit.y());
}

}  // namespace pool::app
