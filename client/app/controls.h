// The controls model: key and mouse events in; the camera, the aim and, on releasing Space, a shot
// command out. Pure (no window, no clock): time passes only through advance(dt).
#pragma once

#include <Eigen/Core>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "client/app/aim.h"
#include "client/app/camera_rig.h"
#include "client/app/input.h"
#include "protocol/command_limits.h"
#include "protocol/shot_request.h"
#include "rules/game_state.h"

namespace pool::app {

/// How fast held keys and the mouse move things. The aim's arrows step on each press and, held
/// past `repeat_delay`, turn at `yaw` (`fine_yaw` with Alt): the heading after a press depends on
/// how long the key was held, never on how that time fell into frames.
struct ControlRates {
  double yaw_step = 0.00436332;       ///< rad per press of left/right (0.25°)
  double fine_yaw_step = 0.00087266;  ///< rad per press with Alt (0.05°)
  double repeat_delay = 0.25;         ///< s held before the arrows turn the cue steadily
  double yaw = 0.5;                   ///< rad/s, left/right held while aiming
  double fine_yaw = 0.01745329;       ///< rad/s, Alt + left/right held (1°/s)
  double fine_mouse_yaw = 0.0002;     ///< rad per pixel, dragging with Alt held
  double tip = 0.5;                   ///< fractions of R per s, Ctrl+arrows
  double elevation = 0.5;             ///< rad/s, A/Z
  double charge_time = 1.5;           ///< s of Space from empty to full power
  double orbit = 1.2;                 ///< rad/s, arrows (watching) or Shift+arrows (aiming)
  double raise = 0.8;                 ///< rad/s
  double zoom = 2.0;                  ///< distance factor per s, S (÷) and X (×)
  double mouse_yaw = 0.003;           ///< rad per pixel, dragging while aiming
  double mouse_orbit = 0.006;         ///< rad per pixel, dragging the view
  double scroll_zoom = 0.9;           ///< distance factor per scroll step
  double stroke_scale = 0.001;        ///< m of cue per pixel of a Ctrl + drag stroke
  double power_step = 0.05;           ///< m/s per press of - / = (the cue speed set exactly)
  double coarse_power_step = 0.5;     ///< m/s per press with Shift
};

/// A mouse stroke's cue: drawn back at most this far (m; the cue stays there while the mouse goes
/// on), and at least kMinStrokeBack before pushing it through to the ball is a stroke.
inline constexpr double kMaxStrokeBack = 0.30;
inline constexpr double kMinStrokeBack = 0.01;

/// Where the cue ball may be put with ball in hand (table frame, m).
struct PlacementArea {
  double half_length = 1.27;      ///< playing surface half extent in x
  double half_width = 0.635;      ///< playing surface half extent in y
  double head_string_x = -0.635;  ///< behind the head string: x < this
  double ball_radius = 0.028575;
  /// Snooker's D (rules::BallInHand::InTheD): the centre of its arc (the brown spot, on the
  /// baulk line) and its radius; 0: the table has no D.
  Eigen::Vector2d d_centre = Eigen::Vector2d::Zero();
  double d_radius = 0.0;
};

/// Drawing and overlay switches the keys toggle.
struct Toggles {
  bool aim_line = true;
  bool vectors = false;
  bool wireframe = false;
  bool textures = true;
  bool lighting = true;
  bool help = false;  ///< the help overlay (F1)
  bool panes = true;  ///< the HUD's panes (Tab hides and shows them)
};

/// What a click may call: the object balls on the table and the pockets' mouths (m).
struct ClickTargets {
  std::vector<std::pair<int, Eigen::Vector2d>> balls;
  std::vector<std::pair<std::string, Eigen::Vector2d>> pockets;
};

/// What a click there would pick or call: an object ball, or (with a ball picked) a pocket.
struct ClickTarget {
  std::optional<int> ball;                       ///< the object ball under the cursor
  std::string pocket;                            ///< else the pocket whose mouth is within reach
  Eigen::Vector2d at = Eigen::Vector2d::Zero();  ///< the ball's centre or the mouth, m
};

/// What the player may do now.
enum class ControlMode : std::uint8_t {
  Watching,  ///< balls moving, the other's turn, spectating
  Aiming,    ///< our turn, balls at rest
};

class Controls {
 public:
  Controls(protocol::CommandLimits limits, PlacementArea area, CameraRig camera,
           ControlRates rates = {});

  /// Our turn starts: aiming from the cue ball at `cue_ball` (m), with the cue ball in hand as
  /// the rules say (a placement starts where the ball lies, moved behind the head string if it
  /// must be). Tip, elevation and the call start afresh, the camera behind the cue ball (its
  /// orbit, height and distance of the last turn dropped); the heading is kept until setYaw.
  void startTurn(const Eigen::Vector3d& cue_ball, rules::BallInHand in_hand);
  /// Turns the cue to `yaw` (rad), the camera behind it (e.g. facing the turn's target).
  void setYaw(double yaw);
  /// The current aim's first contact (the ghost ball's centre, m), told each frame, and what lies
  /// ahead of it (the object ball, the pocket it heads for): the view behind the cue (a new turn,
  /// B) is raised until the contact shows above the cue ball, then frames them all
  /// (CameraRig::frameShot).
  void setContact(const Eigen::Vector3d& contact, std::vector<Eigen::Vector3d> ahead = {});
  /// What lies ahead of the contact, as last told (the object ball, the pocket it heads for).
  const std::vector<Eigen::Vector3d>& ahead() const { return ahead_; }
  /// Moves the cue ball in hand to `at` (kept on the slate, behind the head string when it must
  /// be); nothing without ball in hand.
  void moveCueBall(const Eigen::Vector2d& at);
  /// Back to watching (the shot was sent, or the turn went away).
  void stopAiming();
  ControlMode mode() const { return mode_; }

  void keyDown(Key key, Mods mods);
  void keyUp(Key key);
  /// A press or release at (`x`, `y`) pixels; Alt (`mods.alt`) makes dragging the cue fine. A left
  /// press with Ctrl while aiming starts a stroke: moving the mouse down draws the cue back
  /// (rates' stroke_scale m a pixel, sideways movement ignored), up pushes it through; when the tip
  /// reaches the ball the shot is played at the cue's speed over the last advance (clamped to the
  /// power bar's range, and said so). Letting go before, or Esc, cancels it.
  void mouseButton(MouseButton button, bool down, double x, double y, Mods mods = {});
  void mouseMove(double x, double y);
  void scroll(double steps);
  void setViewport(int width, int height);
  /// Another table from now on (the match's own: three-cushion's carom table): its limits, the
  /// area a cue ball may be placed in and a camera rig round it.
  void setTable(protocol::CommandLimits limits, PlacementArea area, CameraRig camera) {
    limits_ = limits;
    area_ = area;
    camera_ = std::move(camera);
  }

  /// Applies the held keys for `dt` seconds (cue, tip, elevation, power, camera).
  void advance(double dt);

  /// The keys that ask the window for something (R: rematch, N: new game, F11: full screen, Q:
  /// concede, Y / Esc: yes / no to the question asked, I: the instant replay, and a practice
  /// table's keys) pressed since the last call, in order.
  std::vector<Key> takeRequests();

  /// The command of the shot released with Space since the last call, if any.
  std::optional<protocol::ShotRequest> takeShot();

  /// The balls and pockets a click may call this frame: a click (a press and release that does
  /// not move) on an object ball picks it, then a click at a pocket calls it there.
  void setClickTargets(ClickTargets targets) { targets_ = std::move(targets); }
  /// Snooker's nomination this frame: a click on one of `balls` nominates it alone, with no pocket
  /// (a click on it again drops it), C calls no pocket and K declares no safety (snooker has
  /// neither); empty: the game calls a ball in a pocket.
  void setNominable(std::optional<std::vector<int>> balls) { nominable_ = std::move(balls); }
  /// Whether the game has a declared safety (K): the pool games; three-cushion and snooker not.
  void setSafetyDeclared(bool declared) { safety_declared_ = declared; }
  /// The ball clicked, waiting for its pocket.
  std::optional<int> pickedBall() const { return picked_ball_; }
  /// What a click at the cursor would pick or call now (nothing while dragging): the window rings
  /// it.
  std::optional<ClickTarget> hovered() const;

  /// A practice table lets the player drag any object ball (a press on one that then moves);
  /// off, a press on an object ball turns the cue as anywhere else.
  void setBallDragging(bool on) { ball_dragging_ = on; }
  /// An object ball dragged and let go since the last call: its id and where it was let go (m,
  /// kept on the slate; whether the spot is legal is the server's).
  std::optional<std::pair<int, Eigen::Vector2d>> takeBallMove();
  /// The object ball being dragged and where it is now, if any.
  std::optional<std::pair<int, Eigen::Vector2d>> draggedBall() const;

  /// The automatic call for the current aim; ignored once the player chose one.
  void suggestCall(const ShotCall& call);
  /// The answer to the rules' pending choice that goes with the next shot.
  void setOption(protocol::ShotOption option) { aim_.option = option; }

  const AimState& aim() const { return aim_; }
  bool charging() const { return charging_; }
  bool stroking() const { return drag_ == Drag::Stroke; }
  /// What the last mouse stroke came to ("stroke 3.60 m/s", clamped or cancelled); empty once a
  /// new turn starts.
  const std::string& strokeNote() const { return stroke_note_; }
  bool draggingCueBall() const { return drag_ == Drag::CueBall; }
  /// The cue ball's centre while aiming (its placement when in hand), m.
  Eigen::Vector3d cueBall() const;
  rules::BallInHand ballInHand() const { return in_hand_; }
  const CameraRig& camera() const { return camera_; }
  CameraRig& camera() { return camera_; }
  const Toggles& toggles() const { return toggles_; }
  /// The aim aids as the player's settings have them (G and V change them too).
  void setAimAids(bool aim_line, bool vectors) {
    toggles_.aim_line = aim_line;
    toggles_.vectors = vectors;
  }
  const protocol::CommandLimits& limits() const { return limits_; }
  /// A mouse stroke's scale, m of cue a pixel (the player's setting).
  void setStrokeScale(double metres_per_pixel) {
    if (metres_per_pixel > 0) rates_.stroke_scale = metres_per_pixel;
  }
  double strokeScale() const { return rates_.stroke_scale; }

 private:
  enum class Drag : std::uint8_t { None, Cue, View, CueBall, Ball, Stroke };

  void advanceAim(double dt, int side, int updown, Mods mods);
  /// The heading's change from the arrows held this advance (past their repeat delay).
  double heldTurn() const;
  /// Seconds of `key`'s hold past the repeat delay that fell in the last advance.
  double repeatTime(Key key) const;
  void advanceCamera(double dt, int side, int updown);
  void toggle(Key key);
  void cyclePocket();
  void placeCueBall(const Eigen::Vector2d& at);
  bool held(Key key) const { return held_.count(key) != 0; }
  void followCue();
  /// The exact power keys: the cue speed to the next multiple of `step` m/s up (`dir` 1) or down.
  void stepPower(int dir, double step);
  /// A stroke's tip reached the ball at `speed` m/s: the shot, at that speed within the bar's
  /// range.
  void strike(double speed);
  void cancelStroke(const char* why);

  protocol::CommandLimits limits_;
  PlacementArea area_;
  CameraRig camera_;
  ControlRates rates_;
  ControlMode mode_ = ControlMode::Watching;
  AimState aim_;
  Eigen::Vector3d cue_ball_ = Eigen::Vector3d::Zero();
  std::optional<Eigen::Vector3d> contact_;
  std::vector<Eigen::Vector3d> ahead_;
  void behindCue();
  rules::BallInHand in_hand_ = rules::BallInHand::None;
  bool charging_ = false;
  std::optional<protocol::ShotRequest> shot_;
  std::vector<Key> requests_;
  /// A key held: the modifiers it was pressed with and how long it has been down (before and
  /// after the last advance), s.
  struct Held {
    Mods mods;
    double time = 0.0;
    double before = 0.0;
  };
  std::map<Key, Held> held_;
  Toggles toggles_;
  Drag drag_ = Drag::None;
  bool fine_drag_ = false;  ///< the drag started with Alt held
  Eigen::Vector2d pressed_at_ = Eigen::Vector2d::Zero();
  bool moved_ = false;  ///< the mouse moved since the press
  void click(double x, double y);
  std::optional<ClickTarget> targetAt(double x, double y) const;
  ClickTargets targets_;
  std::optional<std::vector<int>> nominable_;  ///< snooker: the balls a click nominates
  bool safety_declared_ = true;                ///< K declares a safety
  std::optional<int> picked_ball_;
  bool ball_dragging_ = false;
  std::pair<int, Eigen::Vector2d> dragged_{0, Eigen::Vector2d::Zero()};  ///< with Drag::Ball
  std::optional<std::pair<int, Eigen::Vector2d>> ball_move_;
  Eigen::Vector2d mouse_ = Eigen::Vector2d::Zero();
  double stroke_drawn_ = 0.0;  ///< the stroke's deepest draw-back so far, m
  double stroke_last_ = 0.0;   ///< its draw-back at the last advance, m
  std::string stroke_note_;
  int width_ = 1280;
  int height_ = 720;
};

}  // namespace pool::app
