// The window's loop: network, script, controls, turns and shots, scene, HUD and lobby.
#include "client/ui/window_app.h"

// clang-format off
#include <glad/gl.h>
#include <GLFW/glfw3.h>
// clang-format on
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <deque>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <thread>

#include "client/app/controls.h"
#include "client/app/input_script.h"
#include "client/app/match_session.h"
#include "client/app/placement_search.h"
#include "client/app/settings.h"
#include "client/app/shot_story.h"
#include "client/app/turn_view.h"
#include "client/render/camera.h"
#include "client/render/eight_ball_room.h"
#include "client/render/renderer.h"
#include "client/render/scene.h"
#include "client/ui/aim_screenshot.h"
#include "client/ui/bot_opponent.h"
#include "client/ui/eight_ball_room_ui.h"
#include "client/ui/hud.h"
#include "client/ui/lobby_screen.h"
#include "client/ui/pane_rects.h"
#include "client/ui/scene_convert.h"
#include "client/ui/window_capture.h"
#include "client/ui/window_glfw.h"
#include "client/ui/window_input.h"
#include "client/ui/window_log.h"
#include "client/ui/window_overlay.h"
#include "client/ui/window_practice.h"
#include "client/ui/window_script.h"
#include "client/ui/window_sound.h"
#include "game/loaded_table.h"
#include "net/dds_error.h"

namespace pool::ui {
namespace {

constexpr double kScriptStep = 1.0 / 60.0;  // s of input time per frame under a script
constexpr std::size_t kNotesShown = 6;
constexpr std::chrono::microseconds kMinFrame(1000000 / 144);  // at most 144 frames a second

protocol::CommandLimits limitsOf(const game::LoadedTable& view) {
  protocol::CommandLimits limits;
  limits.half_length = view.halfLength();
  limits.half_width = view.halfWidth();
  return limits;
}

/// The drawn cue's tip and butt in the table frame and in pixels.
CueStick cueStickOf(const render::CuePlacement& cue, const render::Camera& camera, int width,
                    int height) {
  CueStick s;
  s.tip = {cue.tip.x, cue.tip.y, cue.tip.z};
  s.butt = {cue.butt.x, cue.butt.y, cue.butt.z};
  const glm::vec3 tip = render::projectToPixels(camera, width, height, cue.tip);
  const glm::vec3 butt = render::projectToPixels(camera, width, height, cue.butt);
  s.tip_px = {tip.x, tip.y};
  s.butt_px = {butt.x, butt.y};
  return s;
}

app::PlacementArea areaOf(const game::LoadedTable& view) {
  return {view.halfLength(), view.halfWidth(), view.headStringX(), view.radius()};
}

/// The settings file's path and what it holds (the defaults, and why, when it cannot be used).
struct LoadedSettings {
  std::filesystem::path path;
  app::Settings settings;
  std::string problem;
};

LoadedSettings loadSettingsFor(const WindowOptions& options) {
  LoadedSettings out;
  if (!options.keep_identity) return out;  // --fresh-identity keeps nothing between runs
  out.path = app::defaultSettingsPath();
  if (out.path.empty()) return out;
  auto loaded = app::loadSettings(out.path);
  if (loaded) {
    out.settings = *loaded;
  } else {
    out.problem = "settings not used (the file is left as it is): " + loaded.error();
  }
  return out;
}

class WindowApp {
 public:
  WindowApp(const WindowOptions& options, game::LoadedTable view, render::Scene scene)
      : options_(options),
        settings_(loadSettingsFor(options)),
        view_(std::move(view)),
        window_(options.width, options.height),
        renderer_(scene),
        controls_(limitsOf(view_), areaOf(view_),
                  app::CameraRig(view_.spec.length, view_.spec.width,
                                 static_cast<double>(options.width) / options.height)),
        session_({options.domain, options.name, options.hotseat,
                  options.keep_identity ? client::defaultIdentityDir() : std::filesystem::path(),
                  std::nullopt}),
        sound_(options.mute, settings_.settings.volume),
        practice_(view_, options.practice_file) {
    session_.setListener(&sound_);
    // Under a software renderer the light preset keeps the frame budget (--quality overrides
    // the settings for this run, until the player chooses another in the settings pane).
    const GLubyte* gl_renderer = glGetString(GL_RENDERER);
    gl_renderer_ = gl_renderer ? reinterpret_cast<const char*>(gl_renderer) : "";
    applyQuality(options.quality.empty() ? settings_.settings.quality : options.quality);
    controls_.setAimAids(settings_.settings.aim_line, settings_.settings.vectors);
    controls_.setStrokeScale(settings_.settings.stroke_mm / 1000.0);
    window_.setFullScreen(settings_.settings.full_screen);
    if (!settings_.problem.empty()) addNote({settings_.problem, true});
    installInput(window_.get(), controls_);
    window_.startImGui();
    controls_.setViewport(options.width, options.height);
    if (options.practice) {
      table_options_.practice = true;
      session_.setTableSettings(table_options_.settings());
      session_.play("new");
    } else if (const auto level = bot::levelFromString(options.bot); level) {
      playBot(*level);
    } else if (options.play) {
      session_.play(options.match);
    }
    if (!options.spectate.empty()) session_.spectate(options.spectate);
  }

  void setScript(std::vector<app::ScriptStep> steps) { script_.emplace(std::move(steps)); }

  int run(const std::atomic<bool>& stop) {
    const auto start = std::chrono::steady_clock::now();
    double last = 0.0;
    while (!glfwWindowShouldClose(window_.get()) && !stop && !quit_) {
      const auto frame_start = std::chrono::steady_clock::now();
      const double now =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      if (options_.timeout > 0 && now > options_.timeout) return 3;
      glfwPollEvents();
      frame(now, script_ ? kScriptStep : now - last);
      last = now;
      if (!options_.capture.empty()) capture();
      captureForScript();
      glfwSwapBuffers(window_.get());
      // Without vsync (e.g. under Xvfb) the loop would spin: no more frames than a fast screen.
      std::this_thread::sleep_until(frame_start + kMinFrame);
    }
    return captured_ ? 0 : 1;
  }

 private:
  /// Writes the frame just drawn (read before the swap) when the window is closing.
  void capture() {
    if (!quit_ && !glfwWindowShouldClose(window_.get())) return;
    captured_ = writeFramePng(window_.get(), options_.capture);
    if (!captured_) std::cerr << "could not write " << options_.capture << '\n';
  }

  /// Writes the frame just drawn (read before the swap) where a script's capture step says.
  void captureForScript() {
    if (script_mouse_.capture.empty()) return;
    if (!writeFramePng(window_.get(), script_mouse_.capture)) {
      std::cerr << "could not write " << script_mouse_.capture << '\n';
      captured_ = false;
    }
    script_mouse_.capture.clear();
  }

  void applyScript() {
    if (script_ && playScriptFrame(*script_, controls_, session_, script_mouse_)) quit_ = true;
  }

  // ---- Turns and shots ------------------------------------------------------------------------
  Eigen::Vector3d cueBallOf(const client::MatchView& v) const {
    for (const auto& b : v.balls) {
      if (b.id == physics::kCueBall && physics::onTable(b.state)) return b.pos;
    }
    const Eigen::Vector2d head = view_.context.spots.head_spot;
    return {head.x(), head.y(), view_.radius()};
  }

  void followTurn() {
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
    controls_.startTurn(cueBallOf(*v), v->ball_in_hand);
    aiming_seat_ = shooter;
    aimed_revision_ = v->revision;
    // Ball in hand starts where the rules accept it; the first choice that shoots is preselected.
    if (const auto& at = controls_.aim().cue_ball_at) {
      const auto legal = app::nearestLegalPlacement(v->ball_in_hand, *at, v->balls, view_.context);
      if (legal) controls_.moveCueBall(*legal);
    }
    for (const rules::Choice c : v->options) {
      if (protocol::optionShoots(protocol::optionOf(c))) {
        controls_.setOption(protocol::optionOf(c));
        break;
      }
    }
    // The turn opens behind the cue ball, facing the nearest ball the shooter may hit first.
    if (const auto yaw = app::turnStartYaw(controls_.cueBall().head<2>(), v->balls,
                                           client::gameStateOf(*v), v->settings.game)) {
      controls_.setYaw(*yaw);
    }
  }

  void send(protocol::ShotRequest request) {
    const int seat = aiming_seat_;
    aiming_seat_ = -1;
    // A cue ball put in hand is drawn there until the shot's own frames show it moving.
    const client::MatchView* v = session_.view();
    if (request.cue_ball_at && v && protocol::optionShoots(request.option)) {
      placed_ = Placed{{request.cue_ball_at->x(), request.cue_ball_at->y(), view_.radius()},
                       v->shot_number + 1};
    }
    auto sent = session_.shoot(seat, request);
    if (!sent) {
      addNote({"shot not sent: " + sent.error(), true});
      return;
    }
    if (options_.json) printShotLine(session_.match(), seat, *sent, request);
  }

  void addNote(app::SessionNote note) {
    if (options_.json) printNoteLine(note);
    notes_.push_back(std::move(note));
    while (notes_.size() > kNotesShown) notes_.pop_front();
  }

  void chooseOption(protocol::ShotOption option) {
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

  // ---- One frame ------------------------------------------------------------------------------
  /// The cue strokes through after a shot is sent (a re-rack's harmless stroke shows none); the
  /// viewers see it stroke too.
  void startStroke(const protocol::ShotRequest& shot, double now) {
    if (shot.cue.speed_is_ball) return;
    const auto [aim, ball] = releasedAim(shot);
    stroke_ = Stroke{cueAimOf(aim, ball), now};
    if (aiming_seat_ >= 0) session_.sendAim(aiming_seat_, aim, ball.head<2>(), true, now);
  }

  /// The aim a shot was released with (its power from its speed) and the cue ball it strikes.
  std::pair<app::AimState, Eigen::Vector3d> releasedAim(const protocol::ShotRequest& shot) const {
    app::AimState aim;
    aim.yaw = shot.cue.yaw;
    aim.tip_side = shot.cue.tip_side;
    aim.tip_height = shot.cue.tip_height;
    aim.elevation = shot.cue.elevation;
    const protocol::CommandLimits limits = limitsOf(view_);
    aim.power = (shot.cue.speed - app::kMinCueSpeed) / (limits.max_speed - app::kMinCueSpeed);
    aim.power = std::clamp(aim.power, 0.0, 1.0);
    Eigen::Vector3d ball = controls_.cueBall();
    if (shot.cue_ball_at) ball = {shot.cue_ball_at->x(), shot.cue_ball_at->y(), view_.radius()};
    return {aim, ball};
  }

  /// The live aim of our turn goes out (paced by the session); a remote shooter's stroke starts.
  void liveAim(double now) {
    if (controls_.mode() == app::ControlMode::Aiming && aiming_seat_ >= 0) {
      session_.sendAim(aiming_seat_, controls_.aim(), controls_.cueBall().head<2>(), false, now);
    }
    if (const auto stroke = session_.takeStroke()) {
      const Eigen::Vector3d ball(stroke->cue_ball.x(), stroke->cue_ball.y(), view_.radius());
      stroke_ = Stroke{cueAimOf(stroke->aim, ball), now};
    }
  }

  /// The stroke's cue at `now`, while it lasts.
  void showStroke(double now) {
    if (!stroke_) return;
    const float power =
        render::strokePower(stroke_->aim.power, static_cast<float>(now - stroke_->start));
    if (std::isnan(power)) {
      stroke_.reset();
      return;
    }
    render::CueAim aim = stroke_->aim;
    aim.power = power;
    renderer_.setCue(aim);
  }

  /// The 3-D cue at the aim, the ghost ball at the first contact (with the aim line), and the
  /// aiming view kept above the cue's drawn line.
  void showCue(const app::AimPrediction& prediction, bool ghost) {
    renderer_.setCue(cueAimOf(controls_.aim(), controls_.cueBall()));
    const Eigen::Vector2d c = prediction.contact;
    renderer_.setGhost(ghost ? std::optional<glm::vec3>(glm::vec3(c.x(), c.y(), view_.radius()))
                             : std::nullopt);
    if (const auto& cue = renderer_.cue()) {
      controls_.camera().keepAimAbove(cue->drawn_elevation + app::kEyeOverCue);
    }
  }

  /// Where the cue ball is held in hand (aiming), or put for the shot sent (until its frames).
  std::optional<Eigen::Vector3d> cueBallHeld() {
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

  void drawScene(double now) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.get(), &width, &height);
    if (width <= 0 || height <= 0) return;
    controls_.setViewport(width, height);
    const auto replay = replayed(now);
    const auto balls = replay ? replay : session_.balls(now);
    auto shown = replay
                     ? *replay
                     : withCueBallAt(balls.value_or(std::vector<physics::Ball>{}), cueBallHeld());
    // A practice table's ball being dragged is drawn under the cursor.
    if (const auto dragged = controls_.draggedBall(); dragged && !replay) {
      for (auto& b : shown) {
        if (b.id == dragged->first) b.pos.head<2>() = dragged->second;
      }
    }
    if (balls) renderer_.setBalls(sceneBalls(shown));
    // The watching view follows the cue ball while the balls run, if the player asked for it.
    std::optional<Eigen::Vector3d> chased;
    if (settings_.settings.follow_cue && session_.inMotion() && !replay) {
      for (const auto& b : shown) {
        if (b.id == physics::kCueBall && physics::onTable(b.state)) chased = b.pos;
      }
    }
    controls_.camera().chase(chased);
    renderer_.setCue(std::nullopt);
    renderer_.setGhost(std::nullopt);
    cue_source_ = {};
    if (replay) {
      renderer_.setOverlay({});  // the replay shows the balls only
    } else {
      auto overlay = windowOverlay(controls_, session_.view(), shown, view_);
      placement_problem_ = std::move(overlay.placement_problem);
      renderer_.setOverlay(overlayLines(overlay.lines));
      if (overlay.aim) {
        showCue(*overlay.aim, controls_.toggles().aim_line);
        cue_source_ = "local";
      } else if (const auto followed = session_.followedAim()) {
        // The other shooter's cue, glided toward their latest aim.
        const Eigen::Vector3d ball(followed->cue_ball.x(), followed->cue_ball.y(), view_.radius());
        renderer_.setCue(cueAimOf(followed->aim, ball));
        cue_source_ = "remote";
      }
      if (controls_.mode() != app::ControlMode::Aiming && stroke_) {
        showStroke(now);
        if (renderer_.cue()) cue_source_ = "stroke";
      }
    }
    const app::Toggles& t = controls_.toggles();
    renderer_.setOptions(render::withQuality({t.wireframe, t.textures, t.lighting}, quality_));
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    if (in_room_) {
      if (!room_scene_) room_scene_ = std::make_unique<render::EightBallRoom>();
      room_scene_->setOptions({t.wireframe, t.textures, t.lighting});
      room_scene_->draw(render::EightBallRoom::defaultCamera(), width, height, room_.answer);
      return;
    }
    const render::Camera camera = cameraOf(controls_.camera().view());
    renderer_.draw(camera, width, height);
    drawn(camera, shown, width, height, now);
  }

  /// Where the cue ball was drawn (for scripted drags), and the --log-frames line.
  void drawn(const render::Camera& camera, const std::vector<physics::Ball>& shown, int width,
             int height, double now) {
    DrawnFrame f;
    for (const auto& b : shown) {
      if (b.id != physics::kCueBall || !physics::onTable(b.state)) continue;
      f.cue = b.pos;
      const glm::vec3 p = render::projectToPixels(
          camera, width, height,
          glm::vec3(static_cast<float>(b.pos.x()), static_cast<float>(b.pos.y()),
                    static_cast<float>(b.pos.z())));
      if (p.z >= 0.0f) f.cue_px = Eigen::Vector2d(p.x, p.y);  // not when behind the eye
    }
    script_mouse_.cue_ball = f.cue_px;
    if (!options_.json || !options_.log_frames) return;
    if (const auto& cue = renderer_.cue(); cue && !cue_source_.empty()) {
      f.cue_stick = cueStickOf(*cue, camera, width, height);
      f.cue_source = cue_source_;
    }
    f.live_aim = session_.latestAim();
    f.aim_dropped = session_.aimDropped();
    f.now = now;
    f.shot = session_.motionShot();
    f.moving = session_.inMotion();
    f.play_time = session_.playTime();
    f.aiming = controls_.mode() == app::ControlMode::Aiming;
    f.dragging = controls_.draggingCueBall();
    f.replaying = session_.replay().playing();
    f.replay_time = session_.replay().replayTime();
    f.quality = quality_ == render::Quality::Light ? "light" : "full";
    f.mouse = script_mouse_.at;
    f.capture = script_mouse_.capture;
    const glm::mat4 view = render::viewMatrix(camera);
    const glm::mat4 projection =
        render::projectionMatrix(camera, static_cast<float>(width) / static_cast<float>(height));
    for (int c = 0; c < 4; ++c) {
      for (int r = 0; r < 4; ++r) {
        f.view[static_cast<std::size_t>(4 * c + r)] = view[c][r];
        f.projection[static_cast<std::size_t>(4 * c + r)] = projection[c][r];
      }
    }
    f.width = width;
    f.height = height;
    printDrawnLine(f);
  }

  void drawInterface() {
    // Text grows with tall windows (1 up to 800 px high, 2 from 1600), so panes stay readable.
    int fb_width = 0, fb_height = 0;
    glfwGetFramebufferSize(window_.get(), &fb_width, &fb_height);
    ImGui::GetIO().FontGlobalScale = hudScale(fb_height);
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const auto stage = session_.stage();
    if (in_room_) {
      in_room_ = drawEightBallRoom(room_);
    } else if (stage == app::SessionStage::Lobby || stage == app::SessionStage::Joining) {
      if (const auto choice = drawLobby(session_.lobby(), stage == app::SessionStage::Joining,
                                        options_.hotseat, table_options_)) {
        if (choice->kind == LobbyChoice::Kind::Play) {
          session_.setTableSettings(table_options_.settings());
          session_.play(choice->match);
        }
        if (choice->kind == LobbyChoice::Kind::PlayBot) {
          playBot(static_cast<bot::Level>(table_options_.bot_level));
        }
        if (choice->kind == LobbyChoice::Kind::Spectate) session_.spectate(choice->match);
        if (choice->kind == LobbyChoice::Kind::Cancel) session_.leave();
      }
    } else {
      HudActions actions = drawHud(hudInput());
      // The overhead view frames the table where the panes just laid out leave it clear.
      controls_.camera().setClearArea(clearFraction(view_.spec.length + 2 * app::kOverheadMargin,
                                                    view_.spec.width + 2 * app::kOverheadMargin));
      controls_.camera().setAimArea(clearColumnFraction());
      if (const client::MatchView* v = session_.view(); v && controls_.toggles().panes) {
        practice_.drawPhysicsPane(*v, actions.texts);
      }
      hudActions(actions);
    }
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

  HudInput hudInput() const {
    HudInput in;
    in.view = session_.view();
    in.match = session_.match();
    in.spectating = session_.stage() == app::SessionStage::Spectating;
    in.local_seats = session_.localSeats();
    in.local_shooter = controls_.mode() == app::ControlMode::Aiming ? aiming_seat_ : -1;
    in.live_aim = session_.followedAim();
    in.in_motion = session_.inMotion();
    in.controls = &controls_;
    in.placement_problem = placement_problem_;
    in.last_verdict = session_.lastVerdict();
    in.notes = &notes_;
    in.banner = session_.banner();
    in.log = &session_.shotLog();
    in.help = controls_.toggles().help;
    in.panes = controls_.toggles().panes;
    in.names = session_.names();
    in.settings = currentSettings();
    in.can_concede = canConcede();
    in.can_replay = session_.replay().shot().has_value() && !session_.inMotion();
    in.last_shot = session_.lastShot();
    in.replaying = session_.replay().playing();
    in.concede_asked = concede_asked_;
    in.settings_note = !settings_.problem.empty() ? settings_.problem
                       : settings_.path.empty()   ? "settings are not kept (no config folder)"
                                                  : "kept in " + settings_.path.string();
    return in;
  }

  void hudActions(const HudActions& actions) {
    if (options_.json && actions.texts != hud_texts_) printHudLine(actions.texts);
    hud_texts_ = actions.texts;
    if (actions.option) chooseOption(*actions.option);
    if (actions.rematch) rematch();
    if (actions.concede) concede_asked_ = canConcede();
    if (actions.replay) startReplay(*actions.replay, now_);
    if (actions.concede_answer) answerConcede(*actions.concede_answer);
    if (actions.visit_room) in_room_ = true;
    if (actions.new_game) newGame();
    if (actions.settings) {
      controls_.setAimAids(actions.settings->aim_line, actions.settings->vectors);
      controls_.setStrokeScale(actions.settings->stroke_mm / 1000.0);
      settings_.settings.stroke_mm = actions.settings->stroke_mm;
      settings_.settings.pane_places = actions.settings->pane_places;
      settings_.settings.follow_cue = actions.settings->follow_cue;
      window_.setFullScreen(actions.settings->full_screen);
      settings_.settings.volume = actions.settings->volume;
      if (actions.settings->quality != settings_.settings.quality) {
        settings_.settings.quality = actions.settings->quality;
        applyQuality(settings_.settings.quality);
      }
    }
    keepSettings();
    if (actions.leave) {
      controls_.stopAiming();
      session_.leave();
    }
  }

  /// Leaves a finished match for a free table (the server keeps one open).
  void newGame() {
    controls_.stopAiming();
    aiming_seat_ = -1;
    placed_.reset();
    in_room_ = false;
    session_.leave();
    session_.play();
    addNote({"looking for a free table for a new game", false});
  }

  /// Draws with the preset `chosen` (auto, full or light) from the next frame on, and says which.
  void applyQuality(const std::string& chosen) {
    const auto setting = render::parseQualitySetting(chosen).value_or(render::QualitySetting::Auto);
    quality_ = render::resolveQuality(setting, gl_renderer_);
    const char* preset = quality_ == render::Quality::Light ? "light" : "full";
    addNote({std::string("drawing quality: ") + preset + " (" + chosen + ")", false});
  }

  /// A rematch, unless the opponent has left the table (then the player is told so).
  void rematch() {
    const client::MatchView* v = session_.view();
    if (!v) return;
    const auto local = session_.localSeats();
    for (int s = 0; s < 2; ++s) {
      const auto& seat = v->seats[static_cast<std::size_t>(s)];
      const bool ours = std::find(local.begin(), local.end(), s) != local.end();
      if (!ours && (seat.name.empty() || !seat.connected)) {
        addNote({session_.names()[static_cast<std::size_t>(s)] +
                     " has left the table: no rematch. N starts a new game at a free table.",
                 true});
        return;
      }
    }
    session_.rematch();
    addNote({"rematch asked", false});
  }

  /// The settings as they are now: the toggles, the window, the volume chosen.
  app::Settings currentSettings() const {
    app::Settings s = settings_.settings;
    s.aim_line = controls_.toggles().aim_line;
    s.vectors = controls_.toggles().vectors;
    s.full_screen = window_.fullScreen();
    return s;
  }

  /// Writes the settings when they changed (never over a file that could not be read).
  void keepSettings() {
    const app::Settings now = currentSettings();
    if (now == settings_.settings || settings_.path.empty() || !settings_.problem.empty()) {
      settings_.settings = now;
      return;
    }
    settings_.settings = now;
    if (auto saved = app::saveSettings(settings_.path, now); !saved) {
      settings_.problem = "settings not kept: " + saved.error();
      addNote({settings_.problem, true});
    }
  }

  /// Plays the last shot again at `speed` × real time (never while the balls move).
  void startReplay(double speed, double now) {
    if (session_.inMotion()) {
      addNote({"the balls are moving: the replay waits for them to stop", false});
      return;
    }
    if (!session_.replay().start(now, speed)) {
      addNote({"no shot to replay yet", false});
      return;
    }
    addNote({"replaying shot " + std::to_string(*session_.replay().shot()), false});
  }

  /// The balls of the instant replay at `now`; empty when none is showing. A shot in motion
  /// ends it: the live game is never held up.
  std::optional<std::vector<physics::Ball>> replayed(double now) {
    app::InstantReplay& replay = session_.replay();
    if (!replay.playing()) return std::nullopt;
    if (session_.inMotion()) replay.stop();
    return replay.sample(now);
  }

  /// True when a player at this screen may concede the rack in play (between shots).
  bool canConcede() const {
    const client::MatchView* v = session_.view();
    return v && client::inPlay(v->phase) && session_.stage() == app::SessionStage::Playing &&
           !session_.practiceTable() && !session_.localSeats().empty() && !session_.inMotion();
  }

  /// The player's yes or no to conceding the rack.
  void answerConcede(bool yes) {
    concede_asked_ = false;
    if (!yes) return;
    if (!canConcede() || !session_.concede()) {
      addNote({"no rack to concede now", true});
      return;
    }
    controls_.stopAiming();
    aiming_seat_ = -1;
    addNote({"concession sent", false});
  }

  /// Asks for a fresh table of the lobby's options; a bot of `level` takes its other seat once
  /// this window holds its own (startBotOpponent).
  void playBot(bot::Level level) {
    table_options_.practice = false;
    session_.setTableSettings(table_options_.settings());
    session_.play("new");
    bot_wanted_ = level;
    addNote({"a table for you and the " + botOpponentName(level) + "...", false});
  }

  /// Starts the bot wanted, at the match this window was seated in.
  void startBotOpponent() {
    if (!bot_wanted_) return;
    if (session_.stage() == app::SessionStage::Lobby) bot_wanted_.reset();  // the player cancelled
    if (!bot_wanted_ || session_.stage() != app::SessionStage::Playing) return;
    const std::string why = bot_opponent_.start(options_.domain, session_.match(), *bot_wanted_);
    addNote({why.empty() ? "the " + botOpponentName(*bot_wanted_) + " is coming to the table" : why,
             !why.empty()});
    bot_wanted_.reset();
  }

  /// R, N, F11; Q, then Y or Esc.
  void requests() {
    const client::MatchView* v = session_.view();
    const bool over =
        v && v->phase == client::MatchPhase::Over && session_.stage() == app::SessionStage::Playing;
    if (concede_asked_ && !canConcede()) concede_asked_ = false;
    for (const app::Key key : controls_.takeRequests()) {
      if (key == app::Key::F11) window_.setFullScreen(!window_.fullScreen());
      if (key == app::Key::Q) concede_asked_ = canConcede();
      if (key == app::Key::I) startReplay(1.0, now_);
      if (concede_asked_ && (key == app::Key::Y || key == app::Key::Escape)) {
        answerConcede(key == app::Key::Y);
        continue;  // the answer to the question, nothing else
      }
      if (session_.stage() == app::SessionStage::Playing) {
        PracticeOutcome outcome = practice_.key(key, session_, controls_);
        if (outcome.note) addNote(std::move(*outcome.note));
        if (outcome.shot && aiming_seat_ >= 0) {
          controls_.stopAiming();
          send(std::move(*outcome.shot));
        }
      }
      if (!over) continue;
      if (key == app::Key::N) {
        newGame();
        return;
      }
      if (key == app::Key::R) rematch();
    }
  }

  void frame(double now, double dt) {
    now_ = now;
    session_.poll(now);
    if (options_.json) progress_.report(session_);
    for (auto& note : session_.takeNotes()) addNote(std::move(note));
    followTurn();
    applyScript();
    requests();
    startBotOpponent();
    controls_.setBallDragging(session_.practiceTable());
    if (const auto move = controls_.takeBallMove(); move && session_.view()) {
      practice_.moveBall(*session_.view(), move->first, move->second);
    }
    if (auto note = practice_.step(session_)) addNote(std::move(*note));
    controls_.advance(dt);
    liveAim(now);
    if (auto shot = controls_.takeShot()) {
      session_.replay().stop();  // the live game takes over
      startStroke(*shot, now);
      send(std::move(*shot));
    }
    drawScene(now);
    sound_.update(session_.playTime());
    drawInterface();
  }

  WindowOptions options_;
  LoadedSettings settings_;
  game::LoadedTable view_;
  GlfwWindow window_;
  render::Renderer renderer_;
  render::Quality quality_ = render::Quality::Full;
  std::string gl_renderer_;  ///< GL_RENDERER, which "auto" quality reads
  double now_ = 0.0;         ///< the frame's time on the window's clock (s)
  /// The cue going through after a shot: its aim at release and when.
  struct Stroke {
    render::CueAim aim;
    double start = 0.0;
  };
  std::optional<Stroke> stroke_;
  std::string cue_source_;  ///< whose cue was drawn this frame: local, remote, stroke, or none
  /// A cue ball put in hand for a shot sent: where, and the shot number that will count it.
  struct Placed {
    Eigen::Vector3d at;
    std::uint32_t shot = 0;
  };
  std::optional<Placed> placed_;
  app::Controls controls_;
  app::MatchSession session_;
  SoundListener sound_;
  std::optional<app::ScriptPlayer> script_;
  ScriptMouse script_mouse_;
  int aiming_seat_ = -1;
  std::uint32_t aimed_revision_ = 0;      ///< the state the aim started from (practice tables)
  TableOptions table_options_;            ///< the lobby's options for a fresh table
  std::optional<bot::Level> bot_wanted_;  ///< a bot to start once this window holds its seat
  BotOpponent bot_opponent_;
  PracticeDesk practice_;
  std::deque<app::SessionNote> notes_;
  std::vector<std::string> hud_texts_;  ///< the HUD's texts of the last frame (--json)
  std::string placement_problem_;
  bool in_room_ = false;
  bool concede_asked_ = false;  ///< Q was pressed: the concession waits for Y or Esc
  EightBallRoomState room_;
  std::unique_ptr<render::EightBallRoom> room_scene_;  ///< made on the first visit
  bool quit_ = false;
  ProgressLog progress_;  ///< with --json
  bool captured_ = true;  ///< false once writing the capture failed
};

}  // namespace

int runWindow(const WindowOptions& options, const std::atomic<bool>& stop) {
  std::optional<std::vector<app::ScriptStep>> script;
  if (!options.script.empty()) {
    auto loaded = app::loadScript(options.script);
    if (!loaded) {
      std::cerr << "script: " << loaded.error() << '\n';
      return 2;
    }
    script = std::move(*loaded);
  }
  auto view = game::loadTable(options.table);
  if (!view) {
    std::cerr << "table: " << view.error() << '\n';
    return 2;
  }
  const render::Scene scene = render::rackScene(*view);
  try {
    WindowApp app(options, std::move(*view), scene);
    if (script) app.setScript(std::move(*script));
    return app.run(stop);
  } catch (const net::DdsError& e) {
    std::cerr << "DDS: " << e.what() << '\n';
    return 1;
  } catch (const std::runtime_error& e) {
    std::cerr << "window: " << e.what() << '\n';
    return 1;
  }
}

}  // namespace pool::ui
