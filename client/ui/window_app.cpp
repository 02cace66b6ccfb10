// The window's loop and lifetime: its parts made and wired, then each frame's network, script,
// controls, turns and shots, scene and interface, until it closes.
#include "client/ui/window_app.h"

#include <GLFW/glfw3.h>

#include <chrono>
#include <iostream>
#include <optional>
#include <stdexcept>
#include <thread>

#include "client/app/controls.h"
#include "client/app/input_script.h"
#include "client/app/match_session.h"
#include "client/render/scene.h"
#include "client/ui/aim_screenshot.h"
#include "client/ui/scene_convert.h"
#include "client/ui/window_capture.h"
#include "client/ui/window_commands.h"
#include "client/ui/window_drawn.h"
#include "client/ui/window_frame_view.h"
#include "client/ui/window_input.h"
#include "client/ui/window_interface.h"
#include "client/ui/window_log.h"
#include "client/ui/window_parts.h"
#include "client/ui/window_script.h"
#include "client/ui/window_sound.h"
#include "client/ui/window_stroke.h"
#include "core/text.h"
#include "game/loaded_table.h"
#include "net/dds_error.h"
#include "table/table_spec.h"

namespace pool::ui {
namespace {

constexpr double kScriptStep = 1.0 / 60.0;  // s of input time per frame under a script
constexpr std::chrono::microseconds kMinFrame(1000000 / 144);  // at most 144 frames a second

protocol::CommandLimits limitsOf(const game::LoadedTable& view) {
  protocol::CommandLimits limits;
  limits.half_length = view.halfLength();
  limits.half_width = view.halfWidth();
  return limits;
}

app::PlacementArea areaOf(const game::LoadedTable& view) {
  app::PlacementArea area;
  area.half_length = view.halfLength();
  area.half_width = view.halfWidth();
  area.head_string_x = view.headStringX();
  area.ball_radius = view.radius();
  if (const auto& marks = view.context.snooker) {
    area.d_centre = marks->brown;
    area.d_radius = marks->d_radius;
  }
  return area;
}

class WindowApp {
 public:
  WindowApp(const WindowOptions& options, game::LoadedTable view, render::Scene scene)
      : options_(options),
        settings_(options.keep_identity),
        view_(std::move(view)),
        window_(options.width, options.height),
        scene_(scene),
        controls_(
            limitsOf(view_), areaOf(view_),
            cameraRigFor(scene.geometry, static_cast<double>(options.width) / options.height)),
        session_({options.domain, options.name, options.hotseat,
                  options.keep_identity ? client::defaultIdentityDir() : std::filesystem::path(),
                  std::nullopt}),
        sound_(options.mute, settings_.settings().volume),
        notes_(options.json),
        turn_(session_, controls_, view_, notes_, options.json),
        desk_(session_, controls_, turn_, notes_, options.domain),
        practice_(view_, options.practice_file),
        parts_{view_,  session_, controls_, window_, settings_,
               scene_, notes_,   turn_,     desk_,   practice_},
        interface_(options.json, options.hotseat) {
    session_.setListener(&sound_);
    // Under a software renderer the light preset keeps the frame budget (--quality overrides
    // the settings for this run, until the player chooses another in the settings pane).
    applyQuality(parts_, options.quality.empty() ? settings_.settings().quality : options.quality);
    const app::Settings& s = settings_.settings();
    controls_.setAimAids(s.aim_line, s.vectors);
    controls_.setStrokeScale(s.stroke_mm / 1000.0);
    window_.setFullScreen(s.full_screen);
    if (!settings_.problem().empty()) notes_.add({settings_.problem(), true});
    installInput(window_.get(), controls_);
    window_.startImGui();
    controls_.setViewport(options.width, options.height);
    startWith(options);
  }

  void setScript(std::vector<app::ScriptStep> steps) {
    script_.emplace(std::move(steps));
    interface_.setScriptMouse(&script_mouse_);
  }

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
  /// What the options ask for at once: a practice table, a bot, a seat, a match to watch.
  void startWith(const WindowOptions& options) {
    if (options.practice) {
      desk_.playPractice();
    } else if (const auto level = bot::levelFromString(options.bot); level) {
      desk_.playBot(*level);
    } else if (options.play) {
      session_.play(options.match);
    }
    if (!options.spectate.empty()) session_.spectate(options.spectate);
    if (!options.replay.empty()) session_.showStored(options.replay, options.replay_shot);
  }

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

  void frame(double now, double dt) {
    update(now, dt);
    drawScene(now);
    sound_.update(session_.playTime());
    interface_.draw(parts_, placement_problem_, now);
  }

  /// The network, the turn, the script and the keys, a practice table's commands, the controls
  /// and the shot they release.
  void update(double now, double dt) {
    session_.poll(now);
    followTable();
    if (options_.json) progress_.report(session_);
    for (auto& note : session_.takeNotes()) notes_.add(std::move(note));
    turn_.follow();
    if (script_ && playScriptFrame(*script_, controls_, session_, script_mouse_, now)) quit_ = true;
    handleKeys(parts_, now);
    desk_.startBotOpponent();
    if (!options_.hotseat) desk_.answerTournamentCall();  // an entrant is one player's key
    controls_.setBallDragging(session_.practiceTable());
    if (const auto move = controls_.takeBallMove(); move && session_.view()) {
      practice_.moveBall(*session_.view(), move->first, move->second);
    }
    if (auto note = practice_.step(session_)) notes_.add(std::move(*note));
    controls_.advance(dt);
    liveAim(now);
    if (auto shot = controls_.takeShot()) shoot(std::move(*shot), now);
  }

  /// The table the match in hand is played on (its lobby entry's: three-cushion's carom table),
  /// or in the lobby the table of the stored shot replayed: loaded and drawn from now on when it
  /// is not the one shown. Every part holds the table by reference, so it changes in place; a
  /// table that cannot load leaves the one shown, noted.
  void followTable() {
    std::string table;
    if (const protocol::HistoryShot* stored = session_.stored().shown();
        stored && session_.stage() == app::SessionStage::Lobby) {
      table = stored->table;
    } else if (!session_.match().empty()) {
      const client::LobbyEntry* entry = session_.lobby().find(session_.match());
      if (entry) table = entry->table;
    }
    if (table.empty() || table == view_.spec.name || table == table_refused_) return;
    // A name from a peer names a table of the assets, never a path.
    if (!table::isSpecName(table)) {
      table_refused_ = table;
      notes_.add({"table " + escapedForLog(table) + ": not a table's name", true});
      return;
    }
    auto loaded = game::loadTable(table);
    if (!loaded) {
      table_refused_ = table;
      notes_.add({"table " + table + ": " + loaded.error(), true});
      return;
    }
    view_ = std::move(*loaded);
    const render::Scene table_scene = render::tableScene(view_);
    scene_.setTable(table_scene);
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.get(), &width, &height);
    controls_.setTable(limitsOf(view_), areaOf(view_),
                       cameraRigFor(table_scene.geometry,
                                    static_cast<double>(std::max(width, 1)) / std::max(height, 1)));
    controls_.setViewport(width, height);
  }

  /// The live aim of our turn goes out (paced by the session); a remote shooter's stroke starts.
  void liveAim(double now) {
    turn_.sendLiveAim(now);
    if (const auto stroke = session_.takeStroke()) stroke_.start(followedCue(*stroke, view_), now);
  }

  /// The shot released goes out; the cue strokes through (a re-rack's harmless stroke shows
  /// none), and the viewers see it stroke too.
  void shoot(protocol::ShotRequest shot, double now) {
    session_.replay().stop();  // the live game takes over
    if (!shot.cue.speed_is_ball) {
      const auto [aim, ball] = releasedAim(shot, controls_.cueBall(), view_);
      stroke_.start(cueAimOf(aim, ball), now);
      turn_.sendAim(aim, ball, true, now);
    }
    turn_.send(std::move(shot));
  }

  /// The frame's view handed to the scene, drawn as the table or the Magic Eight Ball room.
  void drawScene(double now) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.get(), &width, &height);
    if (width <= 0 || height <= 0) return;
    controls_.setViewport(width, height);
    const FrameSources from{session_, controls_, turn_,
                            stroke_,  view_,     settings_.settings().follow_cue};
    const FrameView frame = viewFrame(from, now, width, height);
    if (frame.placement_problem) placement_problem_ = *frame.placement_problem;
    scene_.show(frame, controls_.camera());
    if (desk_.inRoom()) {
      scene_.drawRoom(frame.switches, width, height, desk_.room().answer);
      return;
    }
    const render::Camera camera = cameraOf(controls_.camera().view());
    scene_.drawTable(camera, width, height);
    drawn(frame, camera);
  }

  /// Where the cue ball was drawn (for scripted drags), and the --log-frames line.
  void drawn(const FrameView& frame, const render::Camera& camera) {
    DrawnFrame f = drawnFrame(frame, camera);
    script_mouse_.cue_ball = f.cue_px;
    if (!options_.json || !options_.log_frames) return;
    if (const auto& cue = scene_.cue(); cue && !frame.cue_source.empty()) {
      f.cue_stick = cueStickOf(*cue, camera, frame.width, frame.height);
      f.cue_source = frame.cue_source;
    }
    f.quality = scene_.qualityName();
    f.mouse = script_mouse_.at;
    f.capture = script_mouse_.capture;
    printDrawnLine(f);
  }

  WindowOptions options_;
  WindowSettings settings_;
  game::LoadedTable view_;
  GlfwWindow window_;
  WindowScene scene_;
  app::Controls controls_;
  app::MatchSession session_;
  SoundListener sound_;
  WindowNotes notes_;
  TurnDesk turn_;
  MatchDesk desk_;
  PracticeDesk practice_;
  WindowParts parts_;
  WindowInterface interface_;
  CueStroke stroke_;
  std::optional<app::ScriptPlayer> script_;
  ScriptMouse script_mouse_;
  std::string placement_problem_;
  ProgressLog progress_;  ///< with --json
  bool quit_ = false;
  bool captured_ = true;       ///< false once writing the capture failed
  std::string table_refused_;  ///< a match's table that could not load (not tried again)
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
