// Frame time of the client's 3-D scene on the offscreen context (Mesa llvmpipe under Xvfb or EGL,
// or a GPU's driver): a clear-only frame (the baseline), the bare table, and the full scene (the
// pool hall, sixteen balls rolling with their shadows, two pocketed, the lamps, the 3-D cue and
// the ghost ball, overlay lines, the window's Dear ImGui HUD), from the overview and from the
// aiming view, in the high, the full and the light preset, and without the hall. Prints median and
// p99 per frame and the ratio to the baseline; wall time, since llvmpipe renders on its own
// threads, and the CPU time of the whole process (all threads) per frame, which a busy machine does
// not inflate. --size WxH (default 1280x720) and --preset high|full|light (only that preset's
// scenes).
#include <backends/imgui_impl_opengl3.h>
#include <benchmark/benchmark.h>
#include <glad/gl.h>
#include <imgui.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "bench_run.h"
#include "client/app/controls.h"
#include "client/app/match_session.h"
#include "client/render/offscreen.h"
#include "client/render/renderer.h"
#include "client/render/scene.h"
#include "client/ui/hud.h"

namespace {

// The frame's size: 1280×720 unless --size WxH says otherwise.
int kWidth = 1280;
int kHeight = 720;

/// The context and scene, made once for all benchmarks.
struct Bench {
  pool::render::OffscreenContext context{kWidth, kHeight};
  pool::render::Scene scene = *pool::render::rackScene();
  pool::render::Camera camera =
      pool::render::overviewCamera(scene.geometry, float(kWidth) / float(kHeight));
};

std::optional<Bench>& bench() {
  static std::optional<Bench> b;
  return b;
}

/// Costs of one frame, ms.
struct FrameCost {
  std::vector<double> wall;
  std::vector<double> cpu;     ///< all threads of the process
  std::vector<double> first;   ///< each run's first frame (wall), also in `wall`
  std::vector<double> steady;  ///< the other frames (wall)
};

/// Frame costs per benchmark name, every iteration of every run.
std::map<std::string, FrameCost>& samples() {
  static std::map<std::string, FrameCost> s;
  return s;
}

double processCpuMs() {
  timespec t{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) * 1e3 + static_cast<double>(t.tv_nsec) * 1e-6;
}

/// The window's HUD as a player aiming mid-rack sees it: Dear ImGui on its OpenGL 3 backend (the
/// window's GLFW input backend is not needed to draw), the match panel with both seats, the shot
/// panel with the power bar and the tip widget, a verdict and notes.
class Hud {
 public:
  Hud()
      : controls_(pool::protocol::CommandLimits{}, pool::app::PlacementArea{},
                  pool::app::CameraRig(2.54, 1.27, double(kWidth) / kHeight)) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;
    io.DisplaySize = ImVec2(float(kWidth), float(kHeight));
    ImGui_ImplOpenGL3_Init("#version 330 core");
    view_.match = "bench-1";
    view_.phase = pool::client::MatchPhase::Assigned;
    view_.shooter = 0;
    view_.shot_number = 7;
    view_.rack = 1;
    view_.last_verdict = "Ada pocketed the 3 in the foot left corner; Ada shoots again";
    view_.seats[0].name = "Ada";
    view_.seats[1].name = "Bob";
    view_.seats[0].connected = view_.seats[1].connected = true;
    view_.seats[0].balls_left = 5;
    view_.seats[1].balls_left = 6;
    notes_.push_back({"shot 7 of seat 1 accepted", false});
    controls_.startTurn(Eigen::Vector3d(-0.6, 0.1, 0.028575), pool::rules::BallInHand::None);
    controls_.keyDown(pool::app::Key::Space, {});
    controls_.advance(0.4);  // power charging: the bar is drawn part full
  }
  ~Hud() {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui::DestroyContext();
  }
  Hud(const Hud&) = delete;
  Hud& operator=(const Hud&) = delete;

  void draw() {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::NewFrame();
    pool::ui::HudInput in;
    in.view = &view_;
    in.match = view_.match;
    in.local_seats = {0};
    in.local_shooter = 0;
    in.controls = &controls_;
    in.last_verdict = view_.last_verdict;
    in.notes = &notes_;
    (void)pool::ui::drawHud(in);
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  }

 private:
  pool::app::Controls controls_;
  pool::client::MatchView view_;
  std::deque<pool::app::SessionNote> notes_;
};

/// Times `frame` once per iteration, to the end of the GPU work.
template <class Frame>
void timeFrames(benchmark::State& state, const std::string& name, Frame frame) {
  if (!bench()) {
    state.SkipWithError("no OpenGL context");
    return;
  }
  bool first = true;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    const double cpu_start = processCpuMs();
    bench()->context.bind();
    frame();
    glFinish();
    const double cpu = processCpuMs() - cpu_start;
    const auto end = std::chrono::steady_clock::now();
    const double ms = std::chrono::duration<double, std::milli>(end - start).count();
    samples()[name].wall.push_back(ms);
    samples()[name].cpu.push_back(cpu);
    (first ? samples()[name].first : samples()[name].steady).push_back(ms);
    first = false;
    state.SetIterationTime(ms / 1000.0);
    bench()->context.endFrame();
  }
}

/// Sixteen balls moving on circles around the table's middle, rolling (orientation turning
/// about the horizontal axis across their motion), two of them in the trough.
std::vector<pool::render::SceneBall> movingBalls(const pool::render::Scene& scene, double t) {
  std::vector<pool::render::SceneBall> balls = scene.balls;
  for (auto& b : balls) {
    const double phase = 0.4 * b.id + 1.5 * t;
    const double radius = 0.15 + 0.02 * b.id;
    b.pos = Eigen::Vector3d(radius * std::cos(phase) * 2.0, radius * std::sin(phase),
                            scene.ball_radius);
    const Eigen::Vector3d axis(std::cos(phase), std::sin(phase), 0.0);
    b.orientation = Eigen::Quaterniond(Eigen::AngleAxisd(8.0 * t + b.id, axis));
    b.pocketed = b.id == 3 || b.id == 12;
  }
  return balls;
}

void BM_BaselineClearOnly(benchmark::State& state) {
  timeFrames(state, "clear only (baseline)", [] {
    glClearColor(0.1f, 0.1f, 0.12f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  });
}

void BM_TableOnly(benchmark::State& state) {
  if (!bench()) return state.SkipWithError("no OpenGL context");
  pool::render::Scene empty = bench()->scene;
  empty.balls.clear();
  const pool::render::Renderer renderer(empty);
  timeFrames(state, "table only", [&] { renderer.draw(bench()->camera, kWidth, kHeight); });
}

/// The aiming view: behind the rack's cue ball on the head spot, looking at the apex ball (as the
/// window's aiming camera: 0.75 m back, a little over 12° up).
pool::render::Camera aimingCamera() {
  const auto& cue = bench()->scene.balls.front().pos;
  const glm::vec3 c(cue.x(), cue.y(), cue.z());
  return {c + glm::vec3(-0.73f, 0.0f, 0.165f), c, 40.0f};
}

/// The full scene with the given switches (the client's P, T, L keys), from the overview or the
/// aiming view.
void fullScene(benchmark::State& state, const std::string& name,
               const pool::render::RenderOptions& options, bool aiming = false) {
  if (!bench()) return state.SkipWithError("no OpenGL context");
  const pool::render::Camera camera = aiming ? aimingCamera() : bench()->camera;
  pool::render::Renderer renderer(bench()->scene);
  renderer.setOptions(options);
  Hud hud;
  int frame = 0;
  timeFrames(state, name, [&] {
    const double t = frame++ / 60.0;
    renderer.setBalls(movingBalls(bench()->scene, t));
    const auto& cue = bench()->scene.balls.front().pos;
    const glm::vec3 c(cue.x(), cue.y(), cue.z());
    // The cue aimed at the apex, drawn back as the power charges; the ghost ball at the apex.
    const float power = 0.5f + 0.5f * static_cast<float>(std::sin(t));
    renderer.setCue(pool::render::CueAim{c, 0.0f, 0.1f, -0.2f, 0.05f, power});
    renderer.setGhost(glm::vec3(0.58f, 0.0f, c.z));
    renderer.setOverlay({{c, c + glm::vec3(1.2f, 0.1f, 0.0f), {1.0f, 1.0f, 1.0f}},
                         {c - glm::vec3(0.9f, 0.05f, -0.05f), c, {0.8f, 0.6f, 0.3f}},
                         {c, c + glm::vec3(0.0f, 0.3f, 0.0f), {1.0f, 0.2f, 0.2f}}});
    renderer.draw(camera, kWidth, kHeight);
    hud.draw();
  });
}

void BM_FullScene(benchmark::State& state) {
  fullScene(state, "full scene + HUD (16 balls moving, overlay)", {});
}

void BM_FullSceneAimingView(benchmark::State& state) {
  fullScene(state, "full scene + HUD, aiming view", {}, true);
}

void BM_FullSceneLight(benchmark::State& state) {
  fullScene(state, "full scene + HUD, light preset", withQuality({}, pool::render::Quality::Light));
}

void BM_FullSceneAimingViewLight(benchmark::State& state) {
  fullScene(state, "full scene + HUD, aiming view, light",
            withQuality({}, pool::render::Quality::Light), true);
}

void BM_FullSceneHigh(benchmark::State& state) {
  fullScene(state, "full scene + HUD, high preset", withQuality({}, pool::render::Quality::High));
}

void BM_FullSceneAimingViewHigh(benchmark::State& state) {
  fullScene(state, "full scene + HUD, aiming view, high",
            withQuality({}, pool::render::Quality::High), true);
}

void BM_FullSceneNoRoom(benchmark::State& state) {
  pool::render::RenderOptions options;
  options.room = false;
  fullScene(state, "full scene + HUD, no hall", options);
}

void BM_FullSceneNoTextures(benchmark::State& state) {
  fullScene(state, "full scene, textures off", {false, false, true});
}

void BM_FullSceneNoLighting(benchmark::State& state) {
  fullScene(state, "full scene, lighting off", {false, true, false});
}

BENCHMARK(BM_BaselineClearOnly)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_TableOnly)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullScene)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneAimingView)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneLight)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneAimingViewLight)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneHigh)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneAimingViewHigh)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneNoRoom)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneNoTextures)->UseManualTime()->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FullSceneNoLighting)->UseManualTime()->Unit(benchmark::kMillisecond);

std::string loadAverage() {
  double load[3] = {0, 0, 0};
  if (getloadavg(load, 3) != 3) return "unknown";
  char text[64];
  std::snprintf(text, sizeof text, "%.1f %.1f %.1f", load[0], load[1], load[2]);
  return text;
}

double percentile(std::vector<double> v, double p) {
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
  return v[std::min(i, v.size() - 1)];
}

}  // namespace

/// The benchmarks of one preset (--preset): the baseline and the bare table with its full scenes
/// (a name ends in "/manual_time").
const char* presetFilter(const std::string& preset) {
  if (preset == "full")
    return "BM_BaselineClearOnly|BM_TableOnly|BM_FullScene/|BM_FullSceneAimingView/";
  if (preset == "light") {
    return "BM_BaselineClearOnly|BM_TableOnly|BM_FullSceneLight|BM_FullSceneAimingViewLight";
  }
  if (preset == "high") {
    return "BM_BaselineClearOnly|BM_TableOnly|BM_FullSceneHigh|BM_FullSceneAimingViewHigh";
  }
  return nullptr;
}

/// Takes this program's own flags out of `args`: --size WxH and --preset NAME (each also as
/// --flag=value). Returns an error line, or nothing.
std::optional<std::string> takeOwnFlags(std::vector<char*>& args, std::string& filter) {
  for (std::size_t i = 1; i < args.size();) {
    const std::string arg = args[i];
    std::string name = arg, value;
    const auto eq = arg.find('=');
    if (eq != std::string::npos) {
      name = arg.substr(0, eq);
      value = arg.substr(eq + 1);
    }
    if (name != "--size" && name != "--preset") {
      ++i;
      continue;
    }
    std::size_t used = 1;
    if (eq == std::string::npos) {
      if (i + 1 >= args.size()) return name + ": needs a value";
      value = args[i + 1];
      used = 2;
    }
    if (name == "--size") {
      int w = 0, h = 0;
      char tail = 0;
      if (std::sscanf(value.c_str(), "%dx%d%c", &w, &h, &tail) != 2 || w < 16 || h < 16 ||
          w > 8192 || h > 8192) {
        return "--size: WIDTHxHEIGHT, each 16-8192, e.g. 2560x1440";
      }
      kWidth = w;
      kHeight = h;
    } else {
      const char* f = presetFilter(value);
      if (!f) return "--preset: high, full or light";
      filter = std::string("--benchmark_filter=") + f;
    }
    args.erase(args.begin() + static_cast<std::ptrdiff_t>(i),
               args.begin() + static_cast<std::ptrdiff_t>(i + used));
  }
  return std::nullopt;
}

int main(int argc, char** argv) {
  // A frame budget's p99 needs hundreds of frames, not the library's half second (about 40
  // frames, where each run's first frame, which compiles the shaders and uploads the meshes, is
  // the p99): 3 s per run unless the command line says otherwise (the smoke test does).
  std::vector<char*> args(argv, argv + argc);
  std::string preset_filter;
  if (auto error = takeOwnFlags(args, preset_filter)) {
    std::fprintf(stderr, "frame_bench: %s\n", error->c_str());
    return 2;
  }
  if (!preset_filter.empty()) args.insert(args.begin() + 1, preset_filter.data());
  char default_min_time[] = "--benchmark_min_time=3";
  const bool min_time_given = std::any_of(args.begin(), args.end(), [](const char* a) {
    return std::string(a).rfind("--benchmark_min_time", 0) == 0;
  });
  if (!min_time_given) args.insert(args.begin() + 1, default_min_time);
  argc = static_cast<int>(args.size());
  args.push_back(nullptr);
  argv = args.data();
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  try {
    bench().emplace();
  } catch (const std::exception& e) {
    // In CI (CI=true) a missing context is a failure, as it is for the OpenGL tests.
    std::fprintf(stderr, "frame_bench: no OpenGL context (%s); nothing measured%s\n", e.what(),
                 pool::test::runningInCi() ? " (CI=true: a failure)" : "");
    return pool::test::runningInCi() ? 1 : 0;
  }
  std::printf("frame_bench: %dx%d through %s, renderer: %s, OpenGL %s\n", kWidth, kHeight,
              bench()->context.backend().c_str(),
              reinterpret_cast<const char*>(glGetString(GL_RENDERER)),
              reinterpret_cast<const char*>(glGetString(GL_VERSION)));
  pool::bench::CheckedReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  const auto& all = samples();
  const auto base = all.find("clear only (baseline)");
  const double base_median = base == all.end() ? 0.0 : percentile(base->second.wall, 0.5);
  std::printf("\nper frame (draw to glFinish): wall median and p99, process CPU median (p99)\n");
  for (const auto& [name, cost] : all) {
    const double median = percentile(cost.wall, 0.5);
    std::printf(
        "  %-40s frames %6zu   wall median %8.3f ms  p99 %8.3f ms   cpu %8.3f ms"
        " (p99 %8.3f ms)",
        name.c_str(), cost.wall.size(), median, percentile(cost.wall, 0.99),
        percentile(cost.cpu, 0.5), percentile(cost.cpu, 0.99));
    if (base_median > 0) std::printf("   x%.0f the baseline", median / base_median);
    std::printf("\n");
    // Each run starts on fresh GL objects (the benchmark library runs a benchmark several times):
    // its first frame pays for them apart from the frames after it.
    if (!cost.first.empty() && !cost.steady.empty()) {
      std::printf(
          "  %-40s first frame of %zu runs: median %7.3f ms, max %8.3f ms; the others: "
          "p99 %7.3f ms, max %8.3f ms\n",
          "", cost.first.size(), percentile(cost.first, 0.5), percentile(cost.first, 1.0),
          percentile(cost.steady, 0.99), percentile(cost.steady, 1.0));
    }
  }
  std::printf("(load average now %s)\n", loadAverage().c_str());
  benchmark::Shutdown();
  return reporter.exitCode();
}
