// The turn at the window: the aim opened for the shooter of this screen, and the shots sent.
#include "client/ui/window_turn.h"

#include "client/app/placement_search.h"
#include "client/app/turn_view.h"
#include "client/ui/window_log.h"
#include "client/ui/window_overlay.h"

namespace pool::ui {

TurnDesk::TurnDesk(app::MatchSession& session, app::Controls& controls,
                   const game::LoadedTable& table, WindowNotes& notes, bool json)
    : session_(session), controls_(controls), table_(table), notes_(notes), json_(json) {}

void TurnDesk::follow() {
  const int shooter = session_.localShooter();
  const client::MatchView* v = session_.view();
  if (shooter < 0 || !v) {
    if (controls_.mode() == app::ControlMode::Aiming) controls_.stopAiming();
    aiming_seat_ = -1;
    return;
  }
  // A practice table's layout may change under the aim (undo, a rack): the turn starts again.
  const bool same_table = !v->settings.practice || v->revision == aimed_revision_;
  if (controls_.mode() == app::ControlMode::Aiming && shooter == aiming_seat_ && same_table) {
    return;
  }
  start(shooter, *v);
}

void TurnDesk::start(int shooter, const client::MatchView& v) {
  controls_.startTurn(cueBallOf(v), v.ball_in_hand);
  aiming_seat_ = shooter;
  aimed_revision_ = v.revision;
  // Ball in hand starts where the rules accept it; the first choice that shoots is preselected.
  if (const auto& at = controls_.aim().cue_ball_at) {
    const auto legal = app::nearestLegalPlacement(v.ball_in_hand, *at, v.balls, table_.context);
    if (legal) controls_.moveCueBall(*legal);
  }
  for (const rules::Choice c : v.options) {
    if (protocol::optionShoots(protocol::optionOf(c))) {
      controls_.setOption(protocol::optionOf(c));
      break;
    }
  }
  // The turn opens behind the cue ball, facing the nearest ball the shooter may hit first.
  if (const auto yaw = app::turnStartYaw(controls_.cueBall().head<2>(), v.balls,
                                         client::gameStateOf(v), v.settings.game)) {
    controls_.setYaw(*yaw);
  }
}

Eigen::Vector3d TurnDesk::cueBallOf(const client::MatchView& view) const {
  for (const auto& b : view.balls) {
    // The ball the shooter strikes: the cue ball, or in three-cushion the shooter's own.
    if (b.id == view.cue_ball && physics::onTable(b.state)) return b.pos;
  }
  const Eigen::Vector2d head = table_.context.spots.head_spot;
  return {head.x(), head.y(), table_.radius()};
}

void TurnDesk::send(protocol::ShotRequest request) {
  const int seat = aiming_seat_;
  aiming_seat_ = -1;
  // A cue ball put in hand is drawn there until the shot's own frames show it moving.
  const client::MatchView* v = session_.view();
  if (request.cue_ball_at && v && protocol::optionShoots(request.option)) {
    placed_ = Placed{{request.cue_ball_at->x(), request.cue_ball_at->y(), table_.radius()},
                     v->shot_number + 1};
  }
  auto sent = session_.shoot(seat, request);
  if (!sent) {
    notes_.add({"shot not sent: " + sent.error(), true});
    return;
  }
  if (json_) printShotLine(session_.match(), seat, *sent, request);
}

void TurnDesk::chooseOption(protocol::ShotOption option) {
  if (protocol::optionShoots(option)) {
    controls_.setOption(option);
    return;
  }
  // A re-rack carries no shot: sent at once with a harmless stroke the server does not play.
  protocol::ShotRequest request;
  request.cue.speed = 1.0;
  request.cue.speed_is_ball = true;
  request.option = option;
  controls_.stopAiming();
  send(request);
}

void TurnDesk::sendAim(const app::AimState& aim, const Eigen::Vector3d& cue_ball, bool stroke,
                       double now) {
  if (aiming_seat_ >= 0) session_.sendAim(aiming_seat_, aim, cue_ball.head<2>(), stroke, now);
}

void TurnDesk::sendLiveAim(double now) {
  if (controls_.mode() == app::ControlMode::Aiming) {
    sendAim(controls_.aim(), controls_.cueBall(), false, now);
  }
}

void TurnDesk::reset() {
  aiming_seat_ = -1;
  placed_.reset();
}

std::optional<Eigen::Vector3d> TurnDesk::cueBallHeld() {
  if (placed_) {
    const auto playing = session_.motionShot();
    const client::MatchView* v = session_.view();
    if ((playing && *playing >= placed_->shot) || !v || v->shot_number >= placed_->shot) {
      placed_.reset();
    }
  }
  if (auto held = heldCueBall(controls_)) return held;
  if (placed_) return placed_->at;
  return std::nullopt;
}

}  // namespace pool::ui
