// The overlay of a frame from the controls, the aim prediction and the moving balls.
#include "client/ui/window_overlay.h"

#include "rules/placement.h"

namespace pool::ui {
namespace {

/// How far the bank aim aid goes on past its last cushion, m.
constexpr double kBankTail = 0.4;

void append(std::vector<app::OverlaySegment>& lines, const std::vector<app::OverlaySegment>& more) {
  lines.insert(lines.end(), more.begin(), more.end());
}

/// The aim line and cue arrow while aiming, and the placement check of a cue ball in hand.
void addAiming(WindowOverlay& out, app::Controls& controls, const client::MatchView& match,
               const std::vector<physics::Ball>& balls, const game::LoadedTable& view) {
  const app::Toggles& t = controls.toggles();
  const auto prediction = app::predictAim(controls.cueBall().head<2>(), controls.aim().yaw, balls,
                                          view, match.cue_ball);
  const rules::GameState state = client::gameStateOf(match);
  controls.suggestCall(app::autoCall(prediction, state, balls, view, match.settings.game));
  std::vector<Eigen::Vector3d> ahead;  // the object ball and the pocket it heads for
  if (prediction.ball) {
    for (const auto& b : balls) {
      if (b.id == *prediction.ball) ahead.push_back(b.pos);
    }
  }
  if (prediction.pocket >= 0 && prediction.pocket < static_cast<int>(view.pockets.size())) {
    const Eigen::Vector2d mouth = view.pockets[static_cast<std::size_t>(prediction.pocket)].mouth;
    ahead.emplace_back(mouth.x(), mouth.y(), view.radius());
  }
  controls.setContact({prediction.contact.x(), prediction.contact.y(), view.radius()},
                      std::move(ahead));
  controls.setClickTargets(app::clickTargetsFor(match.settings.game, balls, match.cue_ball, view));
  controls.setNominable(app::nominableFor(match.settings.game, state, balls));
  controls.setSafetyDeclared(rules::isPool(match.settings.game));
  if (t.aim_line) {
    append(out.lines, app::aimOverlay(prediction, view.radius()));
    // Off the cushions: three-cushion's route always, a kick's when a cushion comes first.
    const bool carom = match.settings.game == rules::Game::ThreeCushion;
    if (carom || !prediction.ball) {
      const auto bank = app::bankPath(
          controls.cueBall().head<2>(), controls.aim().yaw, balls, view, match.cue_ball,
          carom ? app::kCaromBankCushions : app::kKickBankCushions, kBankTail);
      append(out.lines, app::bankOverlay(bank, view.radius()));
    }
  }
  // What a click would pick (a ball: a yellow ring) or call (a pocket: green round its mouth).
  if (const auto target = controls.hovered()) {
    append(out.lines,
           target->ball
               ? app::ringOverlay(target->at, 1.5 * view.radius(), view.radius(), {1.0, 0.85, 0.1})
               : app::ringOverlay(target->at, 0.08, view.radius() * 0.3, {0.2, 1.0, 0.3}));
  }
  out.aim = prediction;
  if (t.vectors) {
    append(out.lines, app::cueDirectionOverlay(controls.cueBall(), controls.aim().yaw));
  }
  if (controls.aim().cue_ball_at) {
    const auto check = rules::checkCueBallPlacement(
        controls.ballInHand(), *controls.aim().cue_ball_at, balls, view.context);
    out.placement_problem = check.error();
  }
}

}  // namespace

std::vector<physics::Ball> withCueBallAt(std::vector<physics::Ball> balls,
                                         const std::optional<Eigen::Vector3d>& placed) {
  if (!placed) return balls;
  for (auto& b : balls) {
    if (b.id != physics::kCueBall) continue;
    b.pos = *placed;
    b.vel.setZero();
    b.ang_vel.setZero();
    b.state = physics::MotionState::Stationary;
  }
  return balls;
}

std::optional<Eigen::Vector3d> heldCueBall(const app::Controls& controls) {
  if (controls.mode() != app::ControlMode::Aiming || !controls.aim().cue_ball_at) {
    return std::nullopt;
  }
  return controls.cueBall();
}

WindowOverlay windowOverlay(app::Controls& controls, const client::MatchView* match,
                            const std::vector<physics::Ball>& balls,
                            const game::LoadedTable& view) {
  WindowOverlay out;
  if (controls.mode() == app::ControlMode::Aiming && match) {
    addAiming(out, controls, *match, balls, view);
  }
  if (controls.toggles().vectors) append(out.lines, app::motionOverlay(balls));
  return out;
}

}  // namespace pool::ui
