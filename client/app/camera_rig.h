// The camera as the player steers it: an orbit about the table (watching) or about the cue ball,
// behind the cue (aiming), or overhead; changes of view glide; and the ray under a pixel, for
// dragging the cue ball.
#pragma once

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <optional>
#include <utility>
#include <vector>

#include "client/app/clear_area.h"

namespace pool::app {

/// Where the camera is and looks (table frame, m; +z up) and its vertical field of view.
struct ViewPoint {
  Eigen::Vector3d eye = Eigen::Vector3d::Zero();
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double fov_y_deg = 40.0;
};

/// A camera on a sphere about a target.
struct Orbit {
  Eigen::Vector3d target = Eigen::Vector3d::Zero();
  double azimuth = 0.0;    ///< rad: heading from the target to the eye in the table plane (0 = +x)
  double elevation = 0.0;  ///< rad above the table plane
  double distance = 1.0;   ///< m from the target

  ViewPoint view(double fov_y_deg) const;
};

/// The aiming view's least elevation above the cue's drawn line, rad: the eye over the cue, as a
/// player's.
inline constexpr double kEyeOverCue = 0.1745329;  // 10°
/// keepAimAbove raises the aiming view no higher than this, rad (60°): a cue drawn steeper (a
/// ball frozen to a rail struck level must be drawn near vertical to clear it) is seen from here,
/// the shot still framed, rather than from straight above the cue ball.
inline constexpr double kHighestAimEye = 1.0471976;

/// The aiming view's vertical field of view, degrees: wider than the watching view's 40°, as a
/// player down on a shot takes in the cue ball at the foot of the view and the lamps over the far
/// end at its head.
inline constexpr double kAimFovDeg = 45.0;

/// Limits and steps of the camera controls.
struct CameraLimits {
  double min_elevation = 0.03;  ///< rad
  double max_elevation = 1.55;  ///< rad
  double min_distance = 0.25;   ///< m
  double max_distance = 9.0;    ///< m
};

/// How long a change of view takes to glide from the old view to the new one, s.
inline constexpr double kGlideTime = 0.6;
/// The overhead view frames the playing surface and this much beyond each edge (cushions and
/// most of the rails), m.
inline constexpr double kOverheadMargin = 0.16;
/// The overhead view's pan: metres per radian of orbit or raise, per metre of the view's height.
inline constexpr double kOverheadPan = 0.18;

/// `from` moved toward `to` by `s` in [0, 1] (eye and target alike, eased at both ends).
ViewPoint blend(const ViewPoint& from, const ViewPoint& to, double s);

/// The two cameras of the client (and the overhead view) and which one is in use. view() is what
/// is drawn: a change of camera (aiming on or off, behind the cue, overhead, a new turn) glides
/// there over kGlideTime of update() time instead of cutting; steering the camera in use follows
/// at once.
class CameraRig {
 public:
  /// The watching camera frames a table of `table_length` × `table_width` (m) in a viewport of
  /// aspect `aspect` (w / h).
  CameraRig(double table_length, double table_width, double aspect);

  /// Aiming: the view sits behind the cue ball at `cue_ball`, looking along `yaw` (rad).
  void setAiming(bool aiming);
  bool aiming() const { return aiming_; }
  void followCue(const Eigen::Vector3d& cue_ball, double yaw);

  /// Turns the active camera about its target (rad; + = counter-clockwise seen from above).
  void orbit(double d_azimuth);
  /// Raises (+) or lowers the active camera (rad of elevation).
  void raise(double d_elevation);
  /// Raises the aiming camera to at least `elevation` (rad), e.g. above the cue's line (and frames
  /// the last framed shot again from there).
  void keepAimAbove(double elevation);
  /// Multiplies the active camera's distance by `factor` (< 1 zooms in).
  void zoom(double factor);
  /// The watching camera back to the whole table.
  void resetOverview();
  void setAspect(double aspect);

  /// The aiming camera back to its place straight behind the cue ball (height and distance too)
  /// and the overhead view off: what each turn starts with and the B key gives. Glides.
  void behindCue();
  /// Raises the aiming camera (from its height behind the cue, never lowering it) until the ball
  /// at `contact` (the first contact's ghost ball centre) shows clear above the cue ball at
  /// `cue`, so the view frames both.
  void frameAim(const Eigen::Vector3d& cue, const Eigen::Vector3d& contact, double ball_radius);
  /// Then frames the shot: the look-at point moves ahead of the cue ball and beside its line (the
  /// eye stays behind it) until the cue ball and every point of `ahead` (the ghost ball, the
  /// object ball, its pocket) sit in the aim area, centred on it, drawing back (up to 3 m) where
  /// they do not fit. Kept until the next behindCue.
  void frameShot(const Eigen::Vector3d& cue, const std::vector<Eigen::Vector3d>& ahead);
  /// With a light of `lights` (the lamps over the table, table frame) ahead of the eye and within
  /// the aim area's width, frameShot then tilts the view up (its look-at point raised above the
  /// table) until that light is drawn inside the area's top edge, the shade hanging over the
  /// table, as long as every framed point stays inside the area; where no light fits so, the
  /// view stays as framed.
  void setLights(std::vector<Eigen::Vector3d> lights) { lights_ = std::move(lights); }
  /// The part of the window the aiming view draws the shot in, as fractions from the top-left
  /// corner (app::clearColumnFor of the panes; the whole window until told).
  void setAimArea(const ScreenRect& fraction) { aim_area_ = fraction; }
  /// How far ahead of the cue ball and to the left of its line the aiming view looks, m.
  const Eigen::Vector2d& look() const { return look_; }
  /// The view straight down on the whole table on or off (O), framed in the clear area (turned
  /// lengthwise up the screen where that fits it larger) and neither zoomed nor panned. Glides.
  /// While it is on, orbit() and raise() pan it (rad of orbit: the view's height × kOverheadPan)
  /// and zoom() zooms it.
  void setOverhead(bool overhead);
  bool overhead() const { return overhead_; }
  /// The part of the window no pane covers, as fractions of its width and height from the
  /// top-left corner (the whole window until told): the overhead view frames the table there. A
  /// change of more than 1 % of the window glides there.
  void setClearArea(const ScreenRect& fraction);
  const ScreenRect& clearArea() const { return clear_; }
  /// Holds the drawn view where it is (dragging the cue ball) or lets it follow again (a glide
  /// to wherever the camera went meanwhile).
  void hold(bool held);
  bool held() const { return held_.has_value(); }

  /// The watching view follows `ball` (the cue ball while the balls run, when the player's
  /// setting asks), its look-at point easing toward it (it closes 1 − e^(−3 t) of the way in t s);
  /// empty: it stays where it got to.
  void chase(const std::optional<Eigen::Vector3d>& ball) { chase_ = ball; }
  /// Lets `dt` seconds of glide (and chase) pass.
  void update(double dt);
  /// Ends any glide at once (a screenshot draws the view it set up).
  void settle() { glide_.reset(); }
  bool gliding() const { return glide_.has_value(); }

  /// The view drawn: the camera's, or on its way there.
  ViewPoint view() const;
  /// Where the camera in use is (the end of any glide).
  ViewPoint goal() const;
  const Orbit& watching() const { return watch_; }
  const Orbit& aimingOrbit() const { return aim_; }
  double fovY() const { return fov_y_deg_; }

 private:
  Orbit& active() { return aiming_ ? aim_ : watch_; }
  /// Starts a glide from the view drawn now.
  void startGlide();
  Orbit overheadOrbit() const;
  /// The aiming view of `orbit` looking `look` m ahead of the cue ball and left of its line, and
  /// `up` m above it.
  ViewPoint aimView(const Orbit& orbit, const Eigen::Vector2d& look, double up = 0.0) const;
  /// Moves the overhead view by `right` and `up` (rad, as orbit and raise give them).
  void panOverhead(double right, double up);

  double table_length_;
  double table_width_;
  double aspect_;
  double fov_y_deg_ = 40.0;
  bool aiming_ = false;
  CameraLimits limits_;
  Orbit watch_;
  Orbit aim_;
  double aim_turn_ = 0.0;  ///< the aiming camera's azimuth off the line behind the cue, rad
  bool overhead_ = false;
  std::optional<Eigen::Vector3d> chase_;
  ScreenRect clear_{0.0, 0.0, 1.0, 1.0};
  ScreenRect aim_area_{0.0, 0.0, 1.0, 1.0};
  Eigen::Vector2d look_ = Eigen::Vector2d::Zero();  ///< m: ahead of the cue ball, left of its line
  double look_up_ = 0.0;                            ///< m: above the cue ball
  std::vector<Eigen::Vector3d> lights_;
  /// The cue ball and the points the last frameShot framed (until behindCue): keepAimAbove frames
  /// them again when it raises the eye.
  std::optional<std::pair<Eigen::Vector3d, std::vector<Eigen::Vector3d>>> framed_;
  double overhead_zoom_ = 1.0;                              ///< distance factor (S, X, wheel)
  Eigen::Vector2d overhead_pan_ = Eigen::Vector2d::Zero();  ///< m, table frame
  struct Glide {
    ViewPoint from;
    double t = 0.0;  ///< s since it started
  };
  std::optional<Glide> glide_;
  std::optional<ViewPoint> held_;  ///< the view drawn while held
};

/// Where `p` is drawn by `view` in a window of aspect `aspect`, in normalised device coordinates
/// (x right, y up, −1 to 1 across the window); empty behind the eye.
std::optional<Eigen::Vector2d> ndcOf(const ViewPoint& view, double aspect,
                                     const Eigen::Vector3d& p);

/// The point of the horizontal plane z = `plane_z` under pixel (`px`, `py`) (from the top-left
/// corner) of a `width` × `height` viewport seen from `view`; empty when the ray misses it.
std::optional<Eigen::Vector2d> pointUnderPixel(const ViewPoint& view, int width, int height,
                                               double px, double py, double plane_z);

}  // namespace pool::app
