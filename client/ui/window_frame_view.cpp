// A frame's view model from the session, the controls, the turn and the cue's stroke.
#include "client/ui/window_frame_view.h"

#include "client/ui/aim_screenshot.h"
#include "client/ui/scene_convert.h"
#include "client/ui/window_overlay.h"

namespace pool::ui {
namespace {

/// The balls of the instant replay at `now`; empty when none is showing. A shot in motion ends
/// it: the live game is never held up.
std::optional<std::vector<physics::Ball>> replayedBalls(app::MatchSession& session, double now) {
  app::InstantReplay& replay = session.replay();
  if (!replay.playing()) return std::nullopt;
  if (session.inMotion()) replay.stop();
  return replay.sample(now);
}

/// A stored shot's replay, shown in the lobby's stead: its balls at `now` and what the frame's log
/// says of it; none before its shot arrived.
std::optional<StoredDrawn> storedShown(const app::MatchSession& session, double now) {
  const app::StoredReplay& stored = session.stored();
  if (session.stage() != app::SessionStage::Lobby || !stored.isOpen() || !stored.shown()) {
    return std::nullopt;
  }
  auto balls = stored.balls(now);
  if (!balls) return std::nullopt;
  const protocol::HistoryShot& shot = *stored.shown();
  return StoredDrawn{shot.match,       shot.shot_number,   shot.shots,
                     stored.time(now), stored.atRest(now), std::move(*balls)};
}

/// The balls as the match has them, with the cue ball held or placed and a practice table's
/// dragged ball under the cursor.
void showMatchBalls(FrameView& f, const FrameSources& from, double now) {
  const auto balls = from.session.balls(now);
  f.balls_known = balls.has_value();
  f.shown = withCueBallAt(balls.value_or(std::vector<physics::Ball>{}), from.turn.cueBallHeld());
  if (const auto dragged = from.controls.draggedBall()) {
    for (auto& b : f.shown) {
      if (b.id == dragged->first) b.pos.head<2>() = dragged->second;
    }
  }
}

/// The watching view follows the cue ball while the balls run, if the player asked for it.
std::optional<Eigen::Vector3d> chasedCueBall(const FrameView& f, const FrameSources& from) {
  std::optional<Eigen::Vector3d> chased;
  if (!from.follow_cue || !from.session.inMotion() || f.replay) return chased;
  for (const auto& b : f.shown) {
    const client::MatchView* v = from.session.view();
    const int struck = v ? v->cue_ball : physics::kCueBall;  // three-cushion: the shooter's own
    if (b.id == struck && physics::onTable(b.state)) chased = b.pos;
  }
  return chased;
}

/// The overlay and the cue: this screen's aim with its ghost ball, else another shooter's live
/// aim; the stroke after a shot once nobody here aims.
void showAim(FrameView& f, const FrameSources& from, double now) {
  auto overlay = windowOverlay(from.controls, from.session.view(), f.shown, from.table);
  f.placement_problem = std::move(overlay.placement_problem);
  f.overlay = overlayLines(overlay.lines);
  if (overlay.aim) {
    f.cue = cueAimOf(from.controls.aim(), from.controls.cueBall());
    const Eigen::Vector2d c = overlay.aim->contact;
    if (from.controls.toggles().aim_line) f.ghost = glm::vec3(c.x(), c.y(), from.table.radius());
    f.keep_clear.push_back(f.cue->cue_ball);
    for (const Eigen::Vector3d& p : from.controls.ahead()) {
      f.keep_clear.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()),
                                static_cast<float>(p.z()));
    }
    f.cue_source = "local";
  } else if (const auto followed = from.session.followedAim()) {
    // The other shooter's cue, glided toward their latest aim.
    f.cue = followedCue(*followed, from.table);
    f.cue_source = "remote";
  }
  if (from.controls.mode() == app::ControlMode::Aiming) return;
  if (const auto stroke = from.stroke.at(now)) {
    f.cue = stroke;
    f.cue_source = "stroke";
  }
}

/// What the frame's log line says of the session and the controls.
DrawnFrame frameFacts(const FrameSources& from, double now) {
  DrawnFrame d;
  d.now = now;
  d.live_aim = from.session.latestAim();
  d.aim_dropped = from.session.aimDropped();
  d.shot = from.session.motionShot();
  d.moving = from.session.inMotion();
  d.play_time = from.session.playTime();
  d.aiming = from.controls.mode() == app::ControlMode::Aiming;
  d.dragging = from.controls.draggingCueBall();
  d.replaying = from.session.replay().playing();
  d.replay_time = from.session.replay().replayTime();
  return d;
}

}  // namespace

FrameView viewFrame(const FrameSources& from, double now, int width, int height) {
  FrameView f;
  f.width = width;
  f.height = height;
  auto stored = storedShown(from.session, now);
  if (stored) {
    f.replay = true;
    f.balls_known = true;
    f.shown = stored->balls;
  } else if (auto replay = replayedBalls(from.session, now)) {
    f.replay = true;
    f.balls_known = true;
    f.shown = std::move(*replay);
  } else {
    showMatchBalls(f, from, now);
  }
  f.chased = chasedCueBall(f, from);
  if (!f.replay) showAim(f, from, now);  // the replay shows the balls only
  const app::Toggles& t = from.controls.toggles();
  f.switches = {t.wireframe, t.textures, t.lighting};
  f.facts = frameFacts(from, now);
  f.facts.stored = std::move(stored);
  return f;
}

}  // namespace pool::ui
