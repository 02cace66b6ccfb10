// The window's loop: network, script, controls, aim line and call, scene, HUD.
#include "client/ui/window_app.h"

// clang-format off
#include <glad/gl.h>
#include <GLFW/glfw3.h>
// clang-format on
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>
#include <stb_image_write.h>

#include <chrono>
#include <cmath>
#include <deque>
#include <iostream>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <thread>

#include "client/app/aim_line.h"
#include "client/app/controls.h"
#include "client/app/input_script.h"
#include "client/app/match_session.h"
#include "client/app/overlay.h"
#include "client/app/placement_search.h"
#include "client/audio/sound_board.h"
#include "client/bot/ai/table_view.h"
#include "client/bot/shot_command.h"
#include "client/render/eight_ball_room.h"
#include "client/render/renderer.h"
#include "client/render/scene.h"
#include "client/ui/aim_screenshot.h"
#include "client/ui/eight_ball_room_ui.h"
#include "client/ui/glfw_keys.h"
#include "client/ui/hud.h"
#include "client/ui/lobby_screen.h"
#include "client/ui/scene_convert.h"
#include "net/dds_error.h"
#include "rules/placement.h"

namespace pool::ui {
namespace {

constexpr double kScriptStep = 1.0 / 60.0;  // s of input time per frame under a script
constexpr std::size_t kNotesShown = 6;
constexpr std::chrono::microseconds kMinFrame(1000000 / 144);  // at most 144 frames a second

/// GLFW and a window with an OpenGL 3.3 core context; ImGui on top.
class GlfwWindow {
 public:
  GlfwWindow(int width, int height) {
    if (glfwInit() != GLFW_TRUE) throw std::runtime_error("glfwInit failed (is DISPLAY set?)");
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, "pool", nullptr, nullptr);
    if (!window_) {
      glfwTerminate();
      throw std::runtime_error("no OpenGL 3.3 core context");
    }
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
    if (gladLoadGL(reinterpret_cast<GLADloadfunc>(glfwGetProcAddress)) == 0) {
      glfwDestroyWindow(window_);
      glfwTerminate();
      throw std::runtime_error("glad could not load OpenGL 3.3");
    }
  }
  ~GlfwWindow() {
    if (imgui_) {
      ImGui_ImplOpenGL3_Shutdown();
      ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
    }
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  GlfwWindow(const GlfwWindow&) = delete;
  GlfwWindow& operator=(const GlfwWindow&) = delete;

  /// ImGui chains to the callbacks installed before this call.
  void startImGui() {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    imgui_ = true;
  }
  GLFWwindow* get() const { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
  bool imgui_ = false;
};

/// The window's sound: the match's frames and shot logs into a SoundBoard.
class SoundListener final : public app::ShotListener {
 public:
  explicit SoundListener(bool mute) : board_(options(mute)) {}
  void onFrame(const client::TableFrame& frame) override {
    board_.onFrame(frame.shot_number, frame.sim_time, frame.balls);
  }
  void onShot(const client::ShotReport& report) override {
    board_.onShot(report.events, report.shot_number);
  }
  void update(double playback_time) { board_.update(playback_time); }

 private:
  static audio::SoundOptions options(bool mute) {
    audio::SoundOptions o;
    o.mute = mute;
    return o;
  }
  audio::SoundBoard board_;
};

net::CommandLimits limitsOf(const bot::TableView& view) {
  net::CommandLimits limits;
  limits.half_length = view.halfLength();
  limits.half_width = view.halfWidth();
  return limits;
}

app::PlacementArea areaOf(const bot::TableView& view) {
  return {view.halfLength(), view.halfWidth(), view.headStringX(), view.radius()};
}

class WindowApp {
 public:
  WindowApp(const WindowOptions& options, bot::TableView view, render::Scene scene)
      : options_(options),
        view_(std::move(view)),
        window_(options.width, options.height),
        renderer_(scene),
        controls_(limitsOf(view_), areaOf(view_),
                  app::CameraRig(view_.spec.length, view_.spec.width,
                                 static_cast<double>(options.width) / options.height)),
        session_({options.domain, options.name, options.hotseat}),
        sound_(options.mute) {
    session_.setListener(&sound_);
    installCallbacks();
    window_.startImGui();
    controls_.setViewport(options.width, options.height);
    if (options.play) session_.play(options.match);
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
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.get(), &width, &height);
    std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * height * 3);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadBuffer(GL_BACK);
    glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
    stbi_flip_vertically_on_write(1);
    captured_ =
        stbi_write_png(options_.capture.c_str(), width, height, 3, rgb.data(), width * 3) != 0;
    if (!captured_) std::cerr << "could not write " << options_.capture << '\n';
  }

  // ---- Input ----------------------------------------------------------------------------------
  static WindowApp& self(GLFWwindow* w) {
    return *static_cast<WindowApp*>(glfwGetWindowUserPointer(w));
  }

  void installCallbacks() {
    GLFWwindow* w = window_.get();
    glfwSetWindowUserPointer(w, this);
    glfwSetKeyCallback(w, [](GLFWwindow* win, int key, int, int action, int mods) {
      if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
      const auto k = keyOf(key);
      if (!k || action == GLFW_REPEAT) return;
      if (action == GLFW_PRESS) self(win).controls_.keyDown(*k, modsOf(mods));
      if (action == GLFW_RELEASE) self(win).controls_.keyUp(*k);
    });
    glfwSetMouseButtonCallback(w, [](GLFWwindow* win, int button, int action, int) {
      if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
      if (button != GLFW_MOUSE_BUTTON_LEFT && button != GLFW_MOUSE_BUTTON_RIGHT) return;
      double x = 0, y = 0;
      glfwGetCursorPos(win, &x, &y);
      self(win).controls_.mouseButton(
          button == GLFW_MOUSE_BUTTON_LEFT ? app::MouseButton::Left : app::MouseButton::Right,
          action == GLFW_PRESS, x, y);
    });
    glfwSetCursorPosCallback(
        w, [](GLFWwindow* win, double x, double y) { self(win).controls_.mouseMove(x, y); });
    glfwSetScrollCallback(w, [](GLFWwindow* win, double, double dy) {
      if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
      self(win).controls_.scroll(dy);
    });
  }

  void applyScript() {
    if (!script_) return;
    app::ScriptConditions now;
    now.can_aim = controls_.mode() == app::ControlMode::Aiming;
    if (const auto* v = session_.view()) now.shot_number = v->shot_number;
    for (const auto& step : script_->frame(now)) {
      switch (step.kind) {
        case app::ScriptStep::Kind::Down:
          controls_.keyDown(step.key, step.mods);
          break;
        case app::ScriptStep::Kind::Up:
          controls_.keyUp(step.key);
          break;
        case app::ScriptStep::Kind::Quit:
          quit_ = true;
          break;
        default:
          break;
      }
    }
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
    if (controls_.mode() == app::ControlMode::Aiming && shooter == aiming_seat_) return;
    controls_.startTurn(cueBallOf(*v), v->ball_in_hand);
    aiming_seat_ = shooter;
    // Ball in hand starts where the rules accept it; the first choice that shoots is preselected.
    if (const auto& at = controls_.aim().cue_ball_at) {
      const auto legal = app::nearestLegalPlacement(v->ball_in_hand, *at, v->balls, view_.context);
      if (legal) controls_.moveCueBall(*legal);
    }
    for (const rules::Choice c : v->options) {
      if (net::optionShoots(bot::optionOf(c))) {
        controls_.setOption(bot::optionOf(c));
        break;
      }
    }
  }

  void send(net::ShotRequest request) {
    const int seat = aiming_seat_;
    aiming_seat_ = -1;
    auto sent = session_.shoot(seat, request);
    if (!sent) {
      addNote({"shot not sent: " + sent.error(), true});
      return;
    }
    if (!options_.json) return;
    nlohmann::json line{{"event", "shot"},
                        {"match", session_.match()},
                        {"seat", seat},
                        {"seq", *sent},
                        {"yaw", request.cue.yaw},
                        {"tip_side", request.cue.tip_side},
                        {"tip_height", request.cue.tip_height},
                        {"elevation", request.cue.elevation},
                        {"speed", request.cue.speed},
                        {"speed_is_ball", request.cue.speed_is_ball},
                        {"safety", request.safety},
                        {"option", net::toString(request.option)}};
    if (request.called_ball) {
      line["called_ball"] = *request.called_ball;
      line["called_pocket"] = request.called_pocket;
    }
    if (request.cue_ball_at)
      line["cue_ball_at"] = {request.cue_ball_at->x(), request.cue_ball_at->y()};
    std::cout << line.dump() << '\n' << std::flush;
  }

  void addNote(app::SessionNote note) {
    if (options_.json) {
      std::cout << nlohmann::json{{"event", "note"}, {"text", note.text}, {"problem", note.problem}}
                       .dump()
                << '\n'
                << std::flush;
    }
    notes_.push_back(std::move(note));
    while (notes_.size() > kNotesShown) notes_.pop_front();
  }

  void chooseOption(net::ShotOption option) {
    if (net::optionShoots(option)) {
      controls_.setOption(option);
      return;
    }
    // A re-rack carries no shot: sent at once with a harmless stroke the server does not play.
    net::ShotRequest request;
    request.cue.speed = 1.0;
    request.cue.speed_is_ball = true;
    request.option = option;
    controls_.stopAiming();
    send(request);
  }

  // ---- One frame ------------------------------------------------------------------------------
  std::vector<physics::Ball> ballsWithPlacement(std::vector<physics::Ball> balls) const {
    if (!controls_.aim().cue_ball_at) return balls;
    for (auto& b : balls) {
      if (b.id != physics::kCueBall) continue;
      b.pos = controls_.cueBall();
      b.state = physics::MotionState::Stationary;
    }
    return balls;
  }

  /// The cue strokes through after a shot is sent (a re-rack's harmless stroke shows none).
  void startStroke(const net::ShotRequest& shot, double now) {
    if (shot.cue.speed_is_ball) return;
    app::AimState aim;
    aim.yaw = shot.cue.yaw;
    aim.tip_side = shot.cue.tip_side;
    aim.tip_height = shot.cue.tip_height;
    aim.elevation = shot.cue.elevation;
    const net::CommandLimits limits = limitsOf(view_);
    aim.power = (shot.cue.speed - app::kMinCueSpeed) / (limits.max_speed - app::kMinCueSpeed);
    Eigen::Vector3d ball = controls_.cueBall();
    if (shot.cue_ball_at) ball = {shot.cue_ball_at->x(), shot.cue_ball_at->y(), view_.radius()};
    stroke_ = Stroke{cueAimOf(aim, ball), now};
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

  std::vector<app::OverlaySegment> overlay(const std::vector<physics::Ball>& balls) {
    std::vector<app::OverlaySegment> lines;
    const app::Toggles& t = controls_.toggles();
    placement_problem_.clear();
    renderer_.setCue(std::nullopt);
    renderer_.setGhost(std::nullopt);
    if (controls_.mode() == app::ControlMode::Aiming && session_.view()) {
      const auto prediction =
          app::predictAim(controls_.cueBall().head<2>(), controls_.aim().yaw, balls, view_);
      controls_.suggestCall(
          app::autoCall(prediction, client::gameStateOf(*session_.view()), balls, view_));
      if (t.aim_line) {
        const auto aim = app::aimOverlay(prediction, view_.radius());
        lines.insert(lines.end(), aim.begin(), aim.end());
      }
      showCue(prediction, t.aim_line);
      if (t.vectors) {
        const auto cue = app::cueDirectionOverlay(controls_.cueBall(), controls_.aim().yaw);
        lines.insert(lines.end(), cue.begin(), cue.end());
      }
      if (controls_.aim().cue_ball_at) {
        const auto check = rules::checkCueBallPlacement(
            controls_.ballInHand(), *controls_.aim().cue_ball_at, balls, view_.context);
        placement_problem_ = check.reason();
      }
    }
    if (t.vectors) {
      const auto motion = app::motionOverlay(balls);
      lines.insert(lines.end(), motion.begin(), motion.end());
    }
    return lines;
  }

  void drawScene(double now) {
    int width = 0, height = 0;
    glfwGetFramebufferSize(window_.get(), &width, &height);
    if (width <= 0 || height <= 0) return;
    controls_.setViewport(width, height);
    const auto balls = session_.balls(now);
    const auto shown = ballsWithPlacement(balls.value_or(std::vector<physics::Ball>{}));
    if (balls) renderer_.setBalls(sceneBalls(shown));
    renderer_.setOverlay(overlayLines(overlay(shown)));
    if (controls_.mode() != app::ControlMode::Aiming) showStroke(now);
    const app::Toggles& t = controls_.toggles();
    renderer_.setOptions({t.wireframe, t.textures, t.lighting});
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glViewport(0, 0, width, height);
    if (in_room_) {
      if (!room_scene_) room_scene_ = std::make_unique<render::EightBallRoom>();
      room_scene_->setOptions({t.wireframe, t.textures, t.lighting});
      room_scene_->draw(render::EightBallRoom::defaultCamera(), width, height, room_.answer);
      return;
    }
    renderer_.draw(cameraOf(controls_.camera().view()), width, height);
  }

  void drawInterface() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
    const auto stage = session_.stage();
    if (in_room_) {
      in_room_ = drawEightBallRoom(room_);
    } else if (stage == app::SessionStage::Lobby || stage == app::SessionStage::Joining) {
      if (const auto choice =
              drawLobby(session_.lobby(), stage == app::SessionStage::Joining, options_.hotseat)) {
        if (choice->kind == LobbyChoice::Kind::Play) session_.play(choice->match);
        if (choice->kind == LobbyChoice::Kind::Spectate) session_.spectate(choice->match);
        if (choice->kind == LobbyChoice::Kind::Cancel) session_.leave();
      }
    } else {
      hudActions(drawHud(hudInput()));
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
    in.in_motion = session_.inMotion();
    in.controls = &controls_;
    in.placement_problem = placement_problem_;
    in.last_verdict = session_.lastVerdict();
    in.notes = &notes_;
    return in;
  }

  void hudActions(const HudActions& actions) {
    if (actions.option) chooseOption(*actions.option);
    if (actions.rematch) session_.rematch();
    if (actions.visit_room) in_room_ = true;
    if (actions.leave) {
      controls_.stopAiming();
      session_.leave();
    }
  }

  /// With --json: a line for each new state of the match and each shot whose motion starts.
  void reportProgress() {
    if (!options_.json) return;
    const client::MatchView* v = session_.view();
    if (v && (!last_revision_ || *last_revision_ != v->revision)) {
      last_revision_ = v->revision;
      std::cout << nlohmann::json{{"event", "state"},
                                  {"match", v->match},
                                  {"revision", v->revision},
                                  {"phase", client::toString(v->phase)},
                                  {"shot_number", v->shot_number},
                                  {"shooter", v->shooter}}
                       .dump()
                << '\n'
                << std::flush;
    }
    const auto shot = session_.motionShot();
    if (shot && session_.inMotion() && shot != last_motion_) {
      last_motion_ = shot;
      std::cout << nlohmann::json{{"event", "motion"},
                                  {"match", session_.match()},
                                  {"shot_number", *shot}}
                       .dump()
                << '\n'
                << std::flush;
    }
  }

  void frame(double now, double dt) {
    session_.poll(now);
    reportProgress();
    for (auto& note : session_.takeNotes()) addNote(std::move(note));
    followTurn();
    applyScript();
    controls_.advance(dt);
    if (auto shot = controls_.takeShot()) {
      startStroke(*shot, now);
      send(std::move(*shot));
    }
    drawScene(now);
    sound_.update(session_.playTime());
    drawInterface();
  }

  WindowOptions options_;
  bot::TableView view_;
  GlfwWindow window_;
  render::Renderer renderer_;
  /// The cue going through after a shot: its aim at release and when.
  struct Stroke {
    render::CueAim aim;
    double start = 0.0;
  };
  std::optional<Stroke> stroke_;
  app::Controls controls_;
  app::MatchSession session_;
  SoundListener sound_;
  std::optional<app::ScriptPlayer> script_;
  int aiming_seat_ = -1;
  std::deque<app::SessionNote> notes_;
  std::string placement_problem_;
  bool in_room_ = false;
  EightBallRoomState room_;
  std::unique_ptr<render::EightBallRoom> room_scene_;  ///< made on the first visit
  bool quit_ = false;
  std::optional<std::uint32_t> last_revision_;
  std::optional<std::uint32_t> last_motion_;
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
  auto view = bot::loadTableView(options.table);
  if (!view) {
    std::cerr << "table: " << view.error() << '\n';
    return 2;
  }
  auto scene = render::rackScene(options.table);
  if (!scene) {
    std::cerr << "scene: " << scene.error() << '\n';
    return 2;
  }
  try {
    WindowApp app(options, std::move(*view), *scene);
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
