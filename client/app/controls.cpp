// Key and mouse handling of the controls model.
#include "client/app/controls.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "rules/table_context.h"

namespace pool::app {
namespace {

// How far behind the head string a cue ball in hand is put when it must be behind it, m.
constexpr double kHeadStringSetback = 0.01;
// A press and release closer than this (pixels) is a click, not a drag.
constexpr double kClickSlop = 3.0;
// A click this close to a pocket's mouth (m) calls that pocket.
constexpr double kPocketReach = 0.15;

int axis(bool minus, bool plus) {
  return (plus ? 1 : 0) - (minus ? 1 : 0);
}

std::string metresPerSecond(double speed) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f m/s", speed);
  return text;
}

}  // namespace

Controls::Controls(protocol::CommandLimits limits, PlacementArea area, CameraRig camera,
                   ControlRates rates)
    : limits_(limits), area_(area), camera_(std::move(camera)), rates_(rates) {}

void Controls::startTurn(const Eigen::Vector3d& cue_ball, rules::BallInHand in_hand) {
  mode_ = ControlMode::Aiming;
  cue_ball_ = cue_ball;
  in_hand_ = in_hand;
  charging_ = false;
  aim_.power = 0.0;
  aim_.stroke_back.reset();
  stroke_note_.clear();
  // Each turn starts from a plain centre-ball stroke: spin and a raised cue are chosen per shot.
  aim_.tip_side = 0.0;
  aim_.tip_height = 0.0;
  aim_.elevation = 0.0;
  aim_.call = ShotCall{};
  aim_.option = protocol::ShotOption::None;
  aim_.cue_ball_at.reset();
  picked_ball_.reset();
  if (in_hand != rules::BallInHand::None) placeCueBall(cue_ball.head<2>());
  if (drag_ != Drag::None) camera_.hold(false);
  drag_ = Drag::None;
  contact_.reset();
  camera_.setAiming(true);
  behindCue();
}

void Controls::behindCue() {
  camera_.behindCue();
  followCue();
  if (contact_) {
    camera_.frameAim(cueBall(), *contact_, area_.ball_radius);
    std::vector<Eigen::Vector3d> ahead{*contact_};
    ahead.insert(ahead.end(), ahead_.begin(), ahead_.end());
    camera_.frameShot(cueBall(), ahead);
  }
}

void Controls::setContact(const Eigen::Vector3d& contact, std::vector<Eigen::Vector3d> ahead) {
  const bool first = !contact_;
  contact_ = contact;
  ahead_ = std::move(ahead);
  // The turn's first prediction frames the view it opens with.
  if (first && mode_ == ControlMode::Aiming) behindCue();
}

void Controls::setYaw(double yaw) {
  if (!std::isfinite(yaw)) return;
  aim_.yaw = yaw;
  clampAim(aim_, limits_);
  contact_.reset();  // the next prediction frames the new heading
  if (mode_ == ControlMode::Aiming) followCue();
}

void Controls::moveCueBall(const Eigen::Vector2d& at) {
  if (mode_ != ControlMode::Aiming || in_hand_ == rules::BallInHand::None) return;
  placeCueBall(at);
  followCue();
}

void Controls::stopAiming() {
  mode_ = ControlMode::Watching;
  charging_ = false;
  aim_.power = 0.0;
  aim_.stroke_back.reset();
  if (drag_ == Drag::CueBall || drag_ == Drag::Ball) camera_.hold(false);
  if (drag_ != Drag::View) drag_ = Drag::None;
  camera_.setAiming(false);
}

Eigen::Vector3d Controls::cueBall() const {
  if (!aim_.cue_ball_at) return cue_ball_;
  return {aim_.cue_ball_at->x(), aim_.cue_ball_at->y(), area_.ball_radius};
}

void Controls::followCue() {
  camera_.followCue(cueBall(), aim_.yaw);
}

void Controls::placeCueBall(const Eigen::Vector2d& at) {
  if (in_hand_ == rules::BallInHand::InTheD && area_.d_radius > 0.0) {
    // In the D: not past the baulk line, and within the arc (a hair inside its line).
    Eigen::Vector2d in_d(std::min(at.x(), area_.d_centre.x()), at.y());
    const Eigen::Vector2d off = in_d - area_.d_centre;
    const double most = area_.d_radius * (1.0 - 1e-9);
    if (off.norm() > most) in_d = area_.d_centre + off * (most / off.norm());
    aim_.cue_ball_at = in_d;
    return;
  }
  const double r = area_.ball_radius;
  double max_x = area_.half_length - r;
  if (in_hand_ == rules::BallInHand::BehindHeadString) {
    max_x = std::min(max_x, area_.head_string_x - kHeadStringSetback);
  }
  aim_.cue_ball_at =
      Eigen::Vector2d(std::clamp(at.x(), -(area_.half_length - r), max_x),
                      std::clamp(at.y(), -(area_.half_width - r), area_.half_width - r));
}

void Controls::keyDown(Key key, Mods mods) {
  held_[key] = Held{mods};
  const bool aiming = mode_ == ControlMode::Aiming;
  switch (key) {
    case Key::Left:
    case Key::Right:
      // A press turns the cue one step at once, however short it is.
      if (aiming && !mods.ctrl && !mods.shift) {
        const double step = mods.alt ? rates_.fine_yaw_step : rates_.yaw_step;
        aim_.yaw += key == Key::Left ? step : -step;
        clampAim(aim_, limits_);
        followCue();
      }
      break;
    case Key::B:
      if (aiming) {
        behindCue();
      } else {
        camera_.setOverhead(false);
        camera_.resetOverview();
      }
      break;
    case Key::O:
      camera_.setOverhead(!camera_.overhead());
      break;
    case Key::F1:
      toggles_.help = !toggles_.help;
      break;
    case Key::Tab:
      toggles_.panes = !toggles_.panes;
      break;
    case Key::R:
    case Key::N:
    case Key::F11:
    case Key::Q:
    case Key::I:
    case Key::U:
    case Key::Y:
    case Key::J:
    case Key::H:
    case Key::Num8:
    case Key::Num9:
    case Key::Num0:
    case Key::Backspace:
    case Key::F5:
    case Key::F6:
    case Key::F7:
    case Key::Num1:
    case Key::Num2:
    case Key::Num3:
    case Key::Num4:
      requests_.push_back(key);
      break;
    case Key::Space:
      if (aiming && !charging_) {
        charging_ = true;
        aim_.power = 0.0;
      }
      break;
    case Key::Escape:
      requests_.push_back(key);  // also says no to a question asked
      charging_ = false;
      aim_.power = 0.0;
      if (drag_ == Drag::Stroke) cancelStroke("stroke cancelled (Esc)");
      break;
    case Key::Minus:
    case Key::Equal:
      if (aiming && !charging_ && drag_ != Drag::Stroke) {
        stepPower(key == Key::Equal ? 1 : -1,
                  mods.shift ? rates_.coarse_power_step : rates_.power_step);
      }
      break;
    case Key::Enter:
      if (aiming && !charging_ && drag_ != Drag::Stroke) {
        shot_ = requestOf(aim_, limits_);
        stopAiming();
      }
      break;
    case Key::C:
      if (aiming) cyclePocket();
      break;
    case Key::K:
      // A declared safety is a pool game's (snooker nominates, three-cushion declares nothing).
      if (aiming && !nominable_ && safety_declared_) {
        aim_.call.safety = !aim_.call.safety;
        aim_.call.by_player = true;
      }
      break;
    default:
      toggle(key);
  }
}

void Controls::keyUp(Key key) {
  held_.erase(key);
  if (key != Key::Space || !charging_) return;
  charging_ = false;
  if (mode_ != ControlMode::Aiming) return;
  shot_ = requestOf(aim_, limits_);
  stopAiming();
}

void Controls::stepPower(int dir, double step) {
  // To the next multiple of the step, so that presses land on round speeds whatever the bar held
  // (the slowest speed and the limit are kept as they are).
  const double speed = cueSpeedOf(aim_.power, limits_);
  const double steps = speed / step;
  const double near = std::round(steps);
  const double base =
      std::abs(steps - near) < 1e-6 ? near : (dir > 0 ? std::floor(steps) : std::ceil(steps));
  aim_.power = powerOfSpeed((base + dir) * step, limits_);
}

void Controls::strike(double speed) {
  const double played = cueSpeedOf(powerOfSpeed(speed, limits_), limits_);
  if (speed > limits_.max_speed) {
    stroke_note_ = "stroke " + metresPerSecond(speed) + ": over the limit, played at " +
                   metresPerSecond(played);
  } else if (speed < kMinCueSpeed) {
    stroke_note_ =
        "stroke " + metresPerSecond(speed) + ": played at the slowest, " + metresPerSecond(played);
  } else {
    stroke_note_ = "stroke " + metresPerSecond(speed);
  }
  aim_.power = powerOfSpeed(speed, limits_);
  aim_.stroke_back.reset();
  drag_ = Drag::None;
  shot_ = requestOf(aim_, limits_);
  if (speed >= kMinCueSpeed && speed <= limits_.max_speed) shot_->cue.speed = speed;
  stopAiming();
}

void Controls::cancelStroke(const char* why) {
  aim_.stroke_back.reset();
  drag_ = Drag::None;
  stroke_note_ = why;
}

void Controls::toggle(Key key) {
  switch (key) {
    case Key::G:
      toggles_.aim_line = !toggles_.aim_line;
      break;
    case Key::V:
      toggles_.vectors = !toggles_.vectors;
      break;
    case Key::P:
      toggles_.wireframe = !toggles_.wireframe;
      break;
    case Key::T:
      toggles_.textures = !toggles_.textures;
      break;
    case Key::L:
      toggles_.lighting = !toggles_.lighting;
      break;
    default:
      break;
  }
}

void Controls::cyclePocket() {
  // A ball clicked and not yet given a pocket is the one C calls; with no ball called (a safety,
  // or nothing yet) there is no pocket to move on.
  if (nominable_) return;  // snooker calls no pocket
  if (picked_ball_) {
    aim_.call.ball = picked_ball_;
    picked_ball_.reset();
  }
  if (!aim_.call.ball) return;
  const auto& names = rules::pocketNames();
  const auto it = std::find(names.begin(), names.end(), aim_.call.pocket);
  const std::size_t next = it == names.end() ? 0 : (it - names.begin() + 1) % names.size();
  aim_.call.pocket = std::string(names[next]);
  aim_.call.safety = false;
  aim_.call.by_player = true;
}

void Controls::suggestCall(const ShotCall& call) {
  if (aim_.call.by_player) return;
  aim_.call = call;
  aim_.call.by_player = false;
}

void Controls::advance(double dt) {
  if (!(dt > 0)) return;
  for (auto& [key, h] : held_) {
    h.before = h.time;
    h.time += dt;
  }
  camera_.update(dt);
  const int side = axis(held(Key::Left), held(Key::Right));
  const int updown = axis(held(Key::Down), held(Key::Up));
  Mods mods;
  for (Key k : {Key::Left, Key::Right, Key::Up, Key::Down}) {
    if (const auto it = held_.find(k); it != held_.end()) mods = it->second.mods;
  }
  if (drag_ == Drag::Stroke && mode_ == ControlMode::Aiming && aim_.stroke_back) {
    // The tip reached the struck point during this advance: the cue's speed is its travel over
    // the advance (dt is a frame: a script's 1/60 s, the window's measured time).
    const double back = *aim_.stroke_back;
    if (back <= 0.0 && stroke_drawn_ >= kMinStrokeBack) {
      strike((stroke_last_ - back) / dt);
      return;
    }
    if (back <= 0.0) aim_.stroke_back = 0.0;  // not drawn back yet: the tip rests at the ball
    stroke_last_ = *aim_.stroke_back;
  }
  if (mode_ == ControlMode::Aiming) {
    advanceAim(dt, side, updown, mods);
  } else {
    advanceCamera(dt, side, updown);
  }
  const int zoom = axis(held(Key::S), held(Key::X));
  if (zoom != 0) camera_.zoom(std::pow(rates_.zoom, zoom * dt));
  if (mode_ == ControlMode::Aiming && drag_ != Drag::CueBall) followCue();
}

double Controls::repeatTime(Key key) const {
  const auto it = held_.find(key);
  if (it == held_.end()) return 0.0;
  const double delay = rates_.repeat_delay;
  return std::max(0.0, it->second.time - delay) - std::max(0.0, it->second.before - delay);
}

double Controls::heldTurn() const {
  double turn = 0.0;
  for (const Key k : {Key::Left, Key::Right}) {
    const auto it = held_.find(k);
    if (it == held_.end() || it->second.mods.ctrl || it->second.mods.shift) continue;
    const double rate = it->second.mods.alt ? rates_.fine_yaw : rates_.yaw;
    turn += (k == Key::Left ? 1.0 : -1.0) * rate * repeatTime(k);
  }
  return turn;
}

void Controls::advanceAim(double dt, int side, int updown, Mods mods) {
  if (mods.ctrl) {
    aim_.tip_side += side * rates_.tip * dt;
    aim_.tip_height += updown * rates_.tip * dt;
  } else if (mods.shift) {
    advanceCamera(dt, side, updown);
  } else {
    // Right turns the cue clockwise seen from above, as it looks from behind the cue.
    aim_.yaw += heldTurn();
    camera_.raise(updown * rates_.raise * dt);
  }
  aim_.elevation += axis(held(Key::Z), held(Key::A)) * rates_.elevation * dt;
  if (charging_) aim_.power += dt / rates_.charge_time;
  clampAim(aim_, limits_);
}

void Controls::advanceCamera(double dt, int side, int updown) {
  camera_.orbit(side * rates_.orbit * dt);
  camera_.raise(updown * rates_.raise * dt);
}

void Controls::mouseButton(MouseButton button, bool down, double x, double y, Mods mods) {
  mouse_ = {x, y};
  if (!down) {
    if (drag_ == Drag::Stroke) {
      cancelStroke("stroke let go before the cue reached the ball: no shot");
      return;
    }
    if (drag_ == Drag::Cue && !moved_) click(x, y);
    if (drag_ == Drag::Ball) {
      camera_.hold(false);
      if (moved_) {
        ball_move_ = dragged_;
      } else {
        click(x, y);  // a press that did not move is a click (a call)
      }
    }
    if (drag_ == Drag::CueBall) {
      // The view glides from where it held to behind the ball's new spot.
      camera_.hold(false);
      followCue();
    }
    drag_ = Drag::None;
    return;
  }
  fine_drag_ = mods.alt;
  pressed_at_ = {x, y};
  moved_ = false;
  if (button == MouseButton::Right || mode_ != ControlMode::Aiming) {
    drag_ = Drag::View;
    return;
  }
  if (mods.ctrl) {
    drag_ = Drag::Stroke;
    charging_ = false;
    aim_.stroke_back = 0.0;
    stroke_drawn_ = 0.0;
    stroke_last_ = 0.0;
    stroke_note_.clear();
    return;
  }
  // A press on the cue ball in hand picks it up (at a practice table, on any ball); anywhere
  // else it turns the cue.
  drag_ = Drag::Cue;
  const auto hit = pointUnderPixel(camera_.view(), width_, height_, x, y, area_.ball_radius);
  if (ball_dragging_ && hit) {
    for (const auto& [id, at] : targets_.balls) {
      if ((*hit - at).norm() < 1.3 * area_.ball_radius) {
        drag_ = Drag::Ball;
        dragged_ = {id, at};
        camera_.hold(true);
        return;
      }
    }
  }
  if (in_hand_ == rules::BallInHand::None) return;
  if (hit && (*hit - cueBall().head<2>()).norm() < 2.5 * area_.ball_radius) {
    // The camera holds still while the ball is dragged, so the ball stays under the cursor.
    drag_ = Drag::CueBall;
    camera_.hold(true);
  }
}

void Controls::mouseMove(double x, double y) {
  const Eigen::Vector2d delta = Eigen::Vector2d(x, y) - mouse_;
  mouse_ = {x, y};
  // A few pixels of jitter keep a click a click (and do not turn the cue).
  if (drag_ == Drag::Cue && !moved_) {
    if ((mouse_ - pressed_at_).norm() < kClickSlop) return;
    moved_ = true;
    const Eigen::Vector2d held = mouse_ - pressed_at_;
    aim_.yaw -= held.x() * (fine_drag_ ? rates_.fine_mouse_yaw : rates_.mouse_yaw);
    clampAim(aim_, limits_);
    followCue();
    return;
  }
  switch (drag_) {
    case Drag::None:
      return;
    case Drag::Stroke:
      // Down the screen draws the cue back, up pushes it through; sideways does not turn it.
      if (aim_.stroke_back) {
        aim_.stroke_back =
            std::min(*aim_.stroke_back + delta.y() * rates_.stroke_scale, kMaxStrokeBack);
        stroke_drawn_ = std::max(stroke_drawn_, *aim_.stroke_back);
      }
      return;
    case Drag::View:
      camera_.orbit(-delta.x() * rates_.mouse_orbit);
      camera_.raise(delta.y() * rates_.mouse_orbit);
      break;
    case Drag::Cue:
      aim_.yaw -= delta.x() * (fine_drag_ ? rates_.fine_mouse_yaw : rates_.mouse_yaw);
      clampAim(aim_, limits_);
      break;
    case Drag::Ball:
      if ((mouse_ - pressed_at_).norm() >= kClickSlop) moved_ = true;
      if (const auto hit =
              pointUnderPixel(camera_.view(), width_, height_, x, y, area_.ball_radius)) {
        const double r = area_.ball_radius;
        dragged_.second = {std::clamp(hit->x(), -(area_.half_length - r), area_.half_length - r),
                           std::clamp(hit->y(), -(area_.half_width - r), area_.half_width - r)};
      }
      return;
    case Drag::CueBall:
      // The view is held, so the ray under the cursor is the one drawn.
      if (const auto hit =
              pointUnderPixel(camera_.view(), width_, height_, x, y, area_.ball_radius)) {
        placeCueBall(*hit);
      }
      break;
  }
  if (mode_ == ControlMode::Aiming && drag_ != Drag::CueBall) followCue();
}

std::optional<ClickTarget> Controls::targetAt(double x, double y) const {
  if (mode_ != ControlMode::Aiming) return std::nullopt;
  const auto hit = pointUnderPixel(camera_.view(), width_, height_, x, y, area_.ball_radius);
  if (!hit) return std::nullopt;
  for (const auto& [id, at] : targets_.balls) {
    if ((*hit - at).norm() < 1.3 * area_.ball_radius) return ClickTarget{id, {}, at};
  }
  if (!picked_ball_) return std::nullopt;
  const std::pair<std::string, Eigen::Vector2d>* best = nullptr;
  for (const auto& pocket : targets_.pockets) {
    const double d = (*hit - pocket.second).norm();
    if (d < kPocketReach && (!best || d < (*hit - best->second).norm())) best = &pocket;
  }
  if (!best) return std::nullopt;
  return ClickTarget{std::nullopt, best->first, best->second};
}

std::optional<ClickTarget> Controls::hovered() const {
  if (drag_ != Drag::None) return std::nullopt;
  return targetAt(mouse_.x(), mouse_.y());
}

void Controls::click(double x, double y) {
  const auto target = targetAt(x, y);
  if (!target) return;
  if (target->ball && nominable_) {
    // Snooker: the ball alone is the call; the nominated ball clicked again drops it.
    const auto& allowed = *nominable_;
    if (std::find(allowed.begin(), allowed.end(), *target->ball) == allowed.end()) return;
    const bool again = aim_.call.ball == target->ball;
    aim_.call = ShotCall{again ? std::nullopt : target->ball, {}, false, true};
    return;
  }
  if (target->ball) {
    picked_ball_ = target->ball;
    return;
  }
  aim_.call = ShotCall{picked_ball_, target->pocket, false, true};
  picked_ball_.reset();
}

void Controls::scroll(double steps) {
  camera_.zoom(std::pow(rates_.scroll_zoom, steps));
}

void Controls::setViewport(int width, int height) {
  if (width <= 0 || height <= 0) return;
  width_ = width;
  height_ = height;
  camera_.setAspect(static_cast<double>(width) / height);
}

std::optional<std::pair<int, Eigen::Vector2d>> Controls::takeBallMove() {
  auto move = std::move(ball_move_);
  ball_move_.reset();
  return move;
}

std::optional<std::pair<int, Eigen::Vector2d>> Controls::draggedBall() const {
  if (drag_ != Drag::Ball) return std::nullopt;
  return dragged_;
}

std::vector<Key> Controls::takeRequests() {
  std::vector<Key> out;
  out.swap(requests_);
  return out;
}

std::optional<protocol::ShotRequest> Controls::takeShot() {
  auto shot = std::move(shot_);
  shot_.reset();
  return shot;
}

}  // namespace pool::app
