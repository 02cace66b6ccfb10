// The page's pool hall in headless Chromium: the gateway's own table and state messages handed to
// the page (no match on the wire), a lone ball placed beyond each lamp, and its screenshot checked
// at the points the test projects itself from the page's camera and the lamps it was told of:
// each ball's shadow on the felt lies away from its lamp, each lamp's highlight shows on its ball
// where the mirror reflection puts it, the balls' outlines are anti-aliased, both shades hang in
// view and the felt under a lamp is at least 1.5 times as bright as the felt midway between them.
// The same checks fail on a page without shadow maps or anti-aliasing, and a phone gets the light
// mode. A measurement (run by name, see docs/WEB.md) reports frame time, draw calls, triangles and
// downloads in both modes.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <glm/glm.hpp>
#include <iostream>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <thread>

#include "client/web/web_json.h"
#include "support/chromium_page.h"
#include "support/client_fixture.h"
#include "support/display_check.h"
#include "support/page_meter.h"
#include "support/png_image.h"
#include "support/reported_camera.h"
#include "support/web_process.h"
#include "table/table_spec.h"

namespace pool::client::test {
namespace {

using nlohmann::json;
using std::chrono::seconds;

using WebPageLookTest = ClientIntegrationTest;

/// Opens the page (`query` appended: "&light", say) on `match` from pool-web at `port` at the
/// given viewport, with the meter installed first when asked; waits until it is watching.
bool openPage(ChromiumPage& page, std::uint16_t port, const std::string& match, int width,
              int height, bool mobile, const std::string& query, bool meter) {
  if (!page.started()) return false;
  if (!page.open("about:blank", seconds(20))) return false;
  if (!page.setViewport(width, height, mobile, seconds(20))) return false;
  if (meter && !page.call("Page.addScriptToEvaluateOnNewDocument", {{"source", pageMeterScript()}},
                          seconds(10))) {
    return false;
  }
  const std::string url = "http://127.0.0.1:" + std::to_string(port) + "/?match=" + match + query;
  if (!page.call("Page.navigate", {{"url", url}}, seconds(20))) return false;
  for (int i = 0; i < 200; ++i) {
    const auto s = page.evaluate("window.poolTest && window.poolTest.status()", seconds(5));
    if (s && s->is_object() && (*s)["connected"] == true && (*s)["match"] == match) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

/// Hands the page (a fresh one) `table` and the state of `view`, and waits until it has drawn
/// them twice with everything it loads for the table in place; "" or what went wrong.
std::string feed(ChromiumPage& page, const std::string& table, const protocol::MatchView& view) {
  const std::string script = "(() => { try { window.poolTest.receive(" + table +
                             "); window.poolTest.receive(" + web::stateJson(view) +
                             "); return 'ok'; } catch (e) { return String(e); } })()";
  const auto fed = page.evaluate(script, seconds(10));
  if (!fed) return page.lastError();
  if (*fed != "ok") return fed->dump();
  std::string last;
  for (int i = 0; i < 400; ++i) {
    const auto s = page.evaluate("window.poolTest.status()", seconds(5));
    if (s && s->is_object()) {
      last = s->dump();
      // A fresh page counts its frames from its first table's: two of them drawn with the balls.
      const bool ready = !s->contains("ready") || (*s)["ready"] == true;
      if (ready && (*s)["drawn"].size() == view.balls.size() && (*s)["frames"] >= 2) return "";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return "the page never drew the table: " + last;
}

/// A view of `balls` ({id, x, y}) resting on the table.
protocol::MatchView restingView(const std::string& match, double r,
                                const std::vector<std::array<double, 3>>& balls) {
  protocol::MatchView view;
  view.match = match;
  view.revision = 1;
  view.phase = protocol::MatchPhase::Open;
  view.seats[0].name = "ann";
  view.seats[1].name = "bea";
  view.shooter = 0;
  for (const auto& b : balls) {
    physics::Ball ball;
    ball.id = static_cast<int>(b[0]);
    ball.pos = Eigen::Vector3d(b[1], b[2], r);
    view.balls.push_back(ball);
  }
  return view;
}

/// A 9-ball-sized rack of fifteen at the foot spot and the cue ball in the kitchen: what the
/// page draws most of a match.
protocol::MatchView rackView(const std::string& match, double length, double r) {
  std::vector<std::array<double, 3>> balls{{0, -length / 4, 0.1}};
  const double foot = length / 4;
  int id = 1;
  for (int row = 0; row < 5; ++row) {
    for (int k = 0; k <= row; ++k) {
      const double x = foot + row * 2 * r * std::cos(M_PI / 6) * 1.01;
      const double y = (k - row / 2.0) * 2 * r * 1.01;
      balls.push_back({double(id++), x, y});
    }
  }
  return restingView(match, r, balls);
}

/// The page's camera (window.poolTest.camera()) projecting with the test's own arithmetic, CSS
/// pixels from the page's top left (one device pixel each here), and its eye.
struct PageView {
  glm::dmat4 view{1.0}, projection{1.0};
  double left = 0, top = 0, width = 0, height = 0;
  glm::dvec3 eye{0.0};

  glm::dvec2 project(glm::dvec3 p) const {
    const glm::dvec4 clip = projection * view * glm::dvec4(p, 1.0);
    return {left + (clip.x / clip.w + 1.0) / 2.0 * width,
            top + (1.0 - clip.y / clip.w) / 2.0 * height};
  }
};

std::optional<PageView> pageView(ChromiumPage& page) {
  const auto c = page.evaluate("window.poolTest.camera()", seconds(10));
  if (!c || !c->is_object()) return std::nullopt;
  ReportedCamera cam;
  cam.view = matrixOf((*c)["view"]);
  cam.projection = matrixOf((*c)["projection"]);
  if (!cam.mirrored().empty()) return std::nullopt;
  PageView out;
  out.view = glm::dmat4(cam.view);
  out.projection = glm::dmat4(cam.projection);
  const auto& r = (*c)["rect"];
  out.left = r[0];
  out.top = r[1];
  out.width = r[2];
  out.height = r[3];
  out.eye = glm::dvec3(glm::inverse(out.view)[3]);
  return out;
}

/// A pixel's sRGB value (0..255) in linear light, 0..1.
double toLinear(double v) {
  const double c = v / 255.0;
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

/// Relative luminance in linear light of the pixels within `radius` of `at` (their mean).
double linearLuminance(const Image& image, glm::dvec2 at, int radius = 1) {
  double sum = 0;
  int n = 0;
  for (int dy = -radius; dy <= radius; ++dy) {
    for (int dx = -radius; dx <= radius; ++dx) {
      const int x = static_cast<int>(std::lround(at.x)) + dx;
      const int y = static_cast<int>(std::lround(at.y)) + dy;
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      const Rgb& p = image.at(x, y);
      sum += 0.2126 * toLinear(p[0]) + 0.7152 * toLinear(p[1]) + 0.0722 * toLinear(p[2]);
      ++n;
    }
  }
  return n ? sum / n : 0.0;
}

/// The brightest pixel's sRGB luminance within `radius` of `at`, and where it is.
std::pair<double, glm::dvec2> peak(const Image& image, glm::dvec2 at, double radius) {
  double best = -1;
  glm::dvec2 where = at;
  for (int y = static_cast<int>(at.y - radius); y <= static_cast<int>(at.y + radius) + 1; ++y) {
    for (int x = static_cast<int>(at.x - radius); x <= static_cast<int>(at.x + radius) + 1; ++x) {
      if (x < 0 || y < 0 || x >= image.width || y >= image.height) continue;
      if (glm::length(glm::dvec2(x, y) - at) > radius) continue;
      const double l = luminance(image.at(x, y));
      if (l > best) {
        best = l;
        where = {x, y};
      }
    }
  }
  return {best, where};
}

/// A ball as the screenshot shows it: its disc's centre and radius in pixels.
struct Disc {
  glm::dvec2 centre;
  double radius;
};

Disc discOf(const PageView& view, glm::dvec3 centre, double r) {
  const glm::dvec2 c = view.project(centre);
  // The silhouette's radius: the ball seen from the eye subtends asin(r / d).
  const glm::dvec3 to = centre - view.eye;
  const glm::dvec3 side = glm::normalize(glm::cross(to, glm::dvec3(0, 0, 1)));
  const glm::dvec2 e =
      view.project(centre + side * r * glm::length(to) / std::sqrt(glm::dot(to, to) - r * r));
  return {c, glm::length(e - c)};
}

/// What the checks measure on one screenshot.
struct Looks {
  double shadow = 0;     ///< felt beyond the ball from its lamp over felt beside it (worst)
  double highlight = 0;  ///< pixels from the predicted highlight to the ball's brightest (worst)
  double glint = 0;      ///< the weakest lamp highlight's sRGB luminance over its ball's median
  double edges = 1;      ///< share of a ball's outline rays with an in-between pixel (least)
  double shades = 1e9;   ///< least colour difference a shade makes where it hangs in view
  double pools = 1e9;    ///< least luminance of the felt under a lamp over midway between them
  std::string notes;
};

/// The share of the pixels just outside the outline of the ball at `centre` (their centres'
/// rays from the eye pass 0.05 to 0.3 px outside the sphere) that carry some of the ball's colour:
/// more than 15 levels from the felt 1 px further out (the ball's rim, lit or dark, differs from
/// the felt by 50 or more). Unblended, every one of them is felt; anti-aliased, the ball covers
/// part of most. -1 when too few have contrast enough to tell.
double blendedEdges(const Image& image, const PageView& view, glm::dvec3 centre, double r) {
  const glm::dmat4 unproject = glm::inverse(view.projection * view.view);
  const double tan_half = 1.0 / view.projection[1][1];
  const Disc disc = discOf(view, centre, r);
  const auto at = [&](glm::dvec2 p) {
    const Rgb& q = image.at(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
    return glm::dvec3(q[0], q[1], q[2]);
  };
  int pixels = 0, blended = 0;
  const int reach = static_cast<int>(disc.radius) + 3;
  for (int y = int(disc.centre.y) - reach; y <= int(disc.centre.y) + reach; ++y) {
    for (int x = int(disc.centre.x) - reach; x <= int(disc.centre.x) + reach; ++x) {
      const glm::dvec2 p(x + 0.5, y + 0.5);  // the pixel's centre
      const glm::dvec4 far = unproject * glm::dvec4((p.x - view.left) / view.width * 2 - 1,
                                                    1 - (p.y - view.top) / view.height * 2, 1, 1);
      const glm::dvec3 ray = glm::normalize(glm::dvec3(far) / far.w - view.eye);
      const glm::dvec3 to = centre - view.eye;
      const double along = glm::dot(to, ray);
      const double miss = glm::length(to - ray * along);
      const double pixel = along * 2 * tan_half / view.height;  // m a pixel at the ball
      const double out = (miss - r) / pixel;
      if (out < 0.05 || out > 0.3) continue;
      const glm::dvec2 dir = glm::normalize(p - disc.centre);
      const glm::dvec3 b = at(p - dir * (out + 1.5));
      const glm::dvec3 f = at(p + dir * 1.0);
      const double span = glm::length(b - f);
      if (span < 50) continue;
      ++pixels;
      blended += glm::length(at(p) - f) > 15 ? 1 : 0;
    }
  }
  return pixels >= 8 ? double(blended) / pixels : -1.0;
}

/// A lone ball placed beside a lamp, away from the middle of the table.
struct LampBall {
  int id;
  glm::dvec3 centre;
  glm::dvec3 lamp;
};

/// Measures every point of the look on `shot`, from the page's `view` and the table's lamps.
Looks measure(const Image& shot, const Image& bare, const PageView& view,
              const std::vector<LampBall>& lit, const std::vector<glm::dvec3>& others,
              const std::vector<glm::dvec3>& lamps, double r, double shade_radius) {
  Looks m;
  std::ostringstream notes;
  for (const LampBall& b : lit) {
    const Disc disc = discOf(view, b.centre, r);
    // The shadow: the felt just beyond the ball, on the line from the lamp, against the felt as
    // far out on the side nearer the camera (−y), both at the same distance from the lamp.
    const glm::dvec3 away =
        glm::normalize(glm::dvec3(b.centre.x - b.lamp.x, b.centre.y - b.lamp.y, 0));
    const glm::dvec3 ground(b.centre.x, b.centre.y, 0);
    double beyond = 1e9;
    for (const double k : {1.3, 1.45}) {
      beyond = std::min(beyond, linearLuminance(shot, view.project(ground + away * (k * r))));
    }
    const glm::dvec3 aside =
        glm::normalize(glm::dvec3(-away.y, away.x, 0) * (away.x > 0 ? -1.0 : 1.0));  // toward −y
    const double beside = linearLuminance(shot, view.project(ground + aside * (1.6 * r)));
    m.shadow = std::max(m.shadow, beyond / beside);
    notes << "ball " << b.id << ": felt beyond " << beyond << ", beside " << beside << "; ";
    // The highlight: the sphere's point whose normal halves the directions to the lamp and to
    // the eye.
    const glm::dvec3 h =
        glm::normalize(glm::normalize(b.lamp - b.centre) + glm::normalize(view.eye - b.centre));
    const glm::dvec2 predicted = view.project(b.centre + h * r);
    const auto [top, at] = peak(shot, disc.centre, 0.92 * disc.radius);
    std::vector<double> body;
    for (int y = int(disc.centre.y - disc.radius); y <= int(disc.centre.y + disc.radius); ++y) {
      for (int x = int(disc.centre.x - disc.radius); x <= int(disc.centre.x + disc.radius); ++x) {
        if (glm::length(glm::dvec2(x, y) - disc.centre) < 0.8 * disc.radius)
          body.push_back(luminance(shot.at(x, y)));
      }
    }
    std::nth_element(body.begin(), body.begin() + body.size() / 2, body.end());
    const double median = body[body.size() / 2];
    const double near = peak(shot, predicted, 2.5).first;
    m.highlight = std::max(m.highlight, near >= 0.9 * top ? 0.0 : glm::length(at - predicted));
    m.glint = std::min(m.glint == 0 ? 1e9 : m.glint, near / std::max(median, 1.0));
    notes << "highlight predicted (" << predicted.x << ", " << predicted.y << "), brightest " << top
          << " at (" << at.x << ", " << at.y << "), " << near << " near it, body median " << median
          << "; ";
    const double edges = blendedEdges(shot, view, b.centre, r);
    if (edges >= 0) m.edges = std::min(m.edges, edges);
    notes << "outline blended on " << edges << " of its pixels; ";
  }
  for (const glm::dvec3& c : others) {
    const double edges = blendedEdges(shot, view, c, r);
    if (edges >= 0) m.edges = std::min(m.edges, edges);
    notes << "ball at (" << c.x << ", " << c.y << "): outline blended on " << edges
          << " of its pixels; ";
  }
  for (const glm::dvec3& lamp : lamps) {
    // A shade: what it covers in view (`bare` is the page with the shades hidden).
    double least = 1e9;
    for (const double dz : {0.05, 0.1}) {  // the cone's middle (its rim 3 cm below the light)
      for (const double dx : {-0.4, 0.0, 0.4}) {
        const glm::dvec2 a = view.project(lamp + glm::dvec3(dx * shade_radius, 0, dz));
        const int x = static_cast<int>(std::floor(a.x)), y = static_cast<int>(std::floor(a.y));
        if (x < 0 || y < 0 || x >= shot.width || y >= shot.height || bare.pixels.empty()) {
          least = 0;
          continue;
        }
        const Rgb& p = shot.at(x, y);
        const Rgb& q = bare.at(x, y);
        least = std::min(least, glm::length(glm::dvec3(p[0] - q[0], p[1] - q[1], p[2] - q[2])));
      }
    }
    m.shades = std::min(m.shades, least);
    // The felt straight under the lamp against the felt midway between the lamps.
    const double under = linearLuminance(shot, view.project({lamp.x, lamp.y, 0}), 2);
    const glm::dvec3 mid = 0.5 * (lamps.front() + lamps.back());
    const double between = linearLuminance(shot, view.project({mid.x, mid.y, 0}), 2);
    m.pools = std::min(m.pools, under / between);
    notes << "felt under lamp at x " << lamp.x << ": " << under << ", midway " << between << "; ";
  }
  m.notes = notes.str();
  return m;
}

/// A screenshot of the page, what the checks measured on it and the mode the page reported.
struct Shot {
  Image image;
  Looks looks;
  std::string mode;
};

/// pool-web and the scene of the look's tests: the 9-ft table, its lamps, and the black 8 beyond
/// the head lamp, the blue 2 beyond the foot lamp (0.42 m out along the length, inside their
/// cones and far outside the other lamp's), both on the near (−y) half, clear of what the shades
/// hide from the page's camera; the white and the red near the middle for the outlines. The
/// middle of the table and the felt under each lamp stay clear.
class WebLookTest : public ClientIntegrationTest {
 protected:
  void SetUp() override {
    ClientIntegrationTest::SetUp();
    if (chromiumPath().empty()) POOL_NO_DISPLAY("no chromium (Debian's chromium package)");
    open(kWebLook, "web-look");
    const char* root = std::getenv("POOL_WEB_ROOT");  // another page's folder (an earlier one's)
    std::vector<std::string> args = webArgs(domain_);
    if (root) args.back() = root;
    ChildProcess& web = start("pool-web", args, "web");
    port_ = webPort(web);
    ASSERT_NE(port_, 0) << logs();
    const auto spec = table::loadTableSpec("wpa-9ft");
    ASSERT_TRUE(spec) << spec.error();
    r_ = spec->params.ball_radius;
    const auto table = web::tableJson("wpa-9ft");
    ASSERT_TRUE(table) << table.error();
    table_ = *table;
    const json message = json::parse(table_);
    for (const auto& p : message["lamps"]["positions"]) lamps_.emplace_back(p[0], p[1], p[2]);
    ASSERT_EQ(lamps_.size(), 2u);
    shade_radius_ = message["lamps"]["shade_radius"];
    lit_ = {{8, {lamps_[0].x - 0.42, -0.12, r_}, lamps_[0]},
            {2, {lamps_[1].x + 0.42, -0.12, r_}, lamps_[1]}};
    for (const auto& b : lit_) balls_.push_back({double(b.id), b.centre.x, b.centre.y});
    for (const std::array<double, 3> b :
         {std::array<double, 3>{0, -0.25, -0.35}, std::array<double, 3>{3, 0.3, -0.38}}) {
      balls_.push_back(b);
      others_.emplace_back(b[1], b[2], r_);
    }
  }

  /// Opens the page (`query` appended) at the viewport given, hands it the scene, takes its
  /// screenshot (saved as web-look-`name`.png) and measures it.
  Shot take(const std::string& name, int width, int height, bool mobile, const std::string& query) {
    Shot out;
    const auto started = std::chrono::steady_clock::now();
    const protocol::MatchView view = restingView("look-" + name, r_, balls_);
    ChromiumPage page(file("chromium-" + name), width, height);
    EXPECT_TRUE(openPage(page, port_, view.match, width, height, mobile, query, false))
        << page.lastError() << logs();
    const std::string fed = feed(page, table_, view);
    EXPECT_EQ(fed, "") << page.lastError();
    if (!fed.empty()) return out;
    const auto status = page.evaluate("window.poolTest.status()", seconds(5));
    if (status && status->contains("mode")) out.mode = (*status)["mode"];
    EXPECT_TRUE(status && (!status->contains("dressed") || (*status)["dressed"] == true))
        << "the page drew the plain table: pool-web served none of the project's meshes";
    const std::string png = page.screenshot(seconds(20));
    const std::string path = file("web-look-" + name + ".png");
    std::ofstream(path, std::ios::binary) << png;
    ::testing::Test::RecordProperty("web-look-" + name, path);
    out.image = loadPng(path);
    const auto cam = pageView(page);
    EXPECT_TRUE(cam) << page.lastError();
    if (out.image.pixels.empty() || !cam) return out;
    // The same view with the lamps' shades hidden, a frame later, for what they cover.
    Image bare;
    const auto frames = page.evaluate(
        "(() => { const n = window.poolTest.status().frames; window.poolTest.showShades && "
        "window.poolTest.showShades(false); return n; })()",
        seconds(5));
    for (int i = 0; frames && i < 200; ++i) {
      const auto s = page.evaluate("window.poolTest.status().frames", seconds(5));
      if (s && s->is_number() && *s >= frames->get<int>() + 2) {
        const std::string bare_png = page.screenshot(seconds(20));
        const std::string bare_path = file("web-look-" + name + "-bare.png");
        std::ofstream(bare_path, std::ios::binary) << bare_png;
        bare = loadPng(bare_path);
        break;
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    out.looks = measure(out.image, bare, *cam, lit_, others_, lamps_, r_, shade_radius_);
    std::cout << name << " (" << out.mode << ", "
              << std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count()
              << " s): " << out.looks.notes << std::endl;
    return out;
  }

  std::uint16_t port_ = 0;
  double r_ = 0;
  std::string table_;
  std::vector<glm::dvec3> lamps_;
  double shade_radius_ = 0;
  std::vector<LampBall> lit_;
  std::vector<std::array<double, 3>> balls_;
  std::vector<glm::dvec3> others_;
};

// The full mode at 1280 × 720: the five points of the hall's look, each against the threshold the
// scene predicts.
TEST_F(WebLookTest, TheFullModeShowsShadowsHighlightsEdgesShadesAndLampPools) {
  const Shot full = take("full", 1280, 720, false, "&full");
  ASSERT_FALSE(full.image.pixels.empty());
  EXPECT_EQ(full.mode, "full");
  const Looks& m = full.looks;
  // Each ball's shadow: the felt beyond it from its lamp darker than the felt beside it (without
  // a shadow the two differ by about 10 %: beyond is 3 cm farther from the lamp).
  EXPECT_LT(m.shadow, 0.7) << m.notes;
  // Each lamp's highlight: the brightest pixel of its ball within 2.5 px of where the mirror
  // reflection of the lamp puts it, and far brighter than the ball's body.
  EXPECT_EQ(m.highlight, 0.0) << m.notes;
  EXPECT_GT(m.glint, 2.0) << m.notes;
  // Anti-aliased outlines: most pixels just outside each ball's outline carry some of the ball.
  EXPECT_GT(m.edges, 0.5) << m.notes;
  // Both shades in view: where one hangs the page differs from the page with it hidden.
  EXPECT_GT(m.shades, 20.0) << m.notes;
  // The lamps' pools: the felt under each lamp at least 1.5 times as bright as midway.
  EXPECT_GE(m.pools, 1.5) << m.notes;
}

// The checks can fail: the light mode (no shadow maps) without anti-aliasing shows no shadow and
// no blended outline, and they say so.
TEST_F(WebLookTest, WithoutShadowMapsAndAntialiasingTheChecksFail) {
  const Shot plain = take("plain", 1280, 720, false, "&light&antialias=0");
  ASSERT_FALSE(plain.image.pixels.empty());
  EXPECT_EQ(plain.mode, "light");
  EXPECT_GT(plain.looks.shadow, 0.8) << "no shadow maps, yet a shadow: " << plain.looks.notes;
  EXPECT_LT(plain.looks.edges, 0.25) << "no anti-aliasing, yet blended outlines";
  EXPECT_GE(plain.looks.pools, 1.5) << "the light mode's lamps as bright: " << plain.looks.notes;
}

// A phone (390 × 844, emulated as mobile) gets the light mode by itself.
TEST_F(WebLookTest, APhoneGetsTheLightMode) {
  const Shot phone = take("phone", 390, 844, true, "");
  ASSERT_FALSE(phone.image.pixels.empty());
  EXPECT_EQ(phone.mode, "light");
}

// Frame time, draw calls, triangles and downloads of the page showing a rack on the 9-ft table,
// at 1280 × 720 (a desktop window) and 390 × 844 (a phone, emulated as mobile), each in a fresh
// browser. Not a check: a measurement, run by name with --gtest_also_run_disabled_tests;
// POOL_WEB_SHOTS names a folder for its screenshots.
TEST_F(WebPageLookTest, DISABLED_MeasuresFrameTimeDrawCallsAndDownloads) {
  if (chromiumPath().empty()) POOL_NO_DISPLAY("no chromium (Debian's chromium package)");
  open(kWebLookMeter, "web-look-meter");
  // POOL_WEB_ROOT: another page's folder to measure (an earlier version's, say).
  const char* root = std::getenv("POOL_WEB_ROOT");
  std::vector<std::string> args = webArgs(domain_);
  if (root) args.back() = root;  // webArgs ends with its --root's folder
  ChildProcess& web = start("pool-web", args, "web");
  const std::uint16_t port = webPort(web);
  ASSERT_NE(port, 0) << logs();
  const auto spec = table::loadTableSpec("wpa-9ft");
  ASSERT_TRUE(spec) << spec.error();
  const auto table = web::tableJson("wpa-9ft");
  ASSERT_TRUE(table) << table.error();
  const char* shots = std::getenv("POOL_WEB_SHOTS");
  const char* label = std::getenv("POOL_WEB_SHOT_LABEL");
  struct Case {
    const char* name;
    int width, height;
    bool mobile;
    const char* query;
  };
  for (const Case& c :
       {Case{"1280x720", 1280, 720, false, "&full"}, Case{"390x844", 390, 844, true, ""},
        Case{"1280x720-light", 1280, 720, false, "&light"},
        Case{"1280x720-no-shadows", 1280, 720, false, "&full&shadows=0"},
        Case{"1280x720-no-antialias", 1280, 720, false, "&full&antialias=0"}}) {
    const protocol::MatchView view =
        rackView(std::string("meter-") + c.name, spec->length, spec->params.ball_radius);
    ChromiumPage page(file(std::string("chromium-") + c.name), c.width, c.height);
    ASSERT_TRUE(openPage(page, port, view.match, c.width, c.height, c.mobile, c.query, true))
        << page.lastError() << logs();
    const std::string fed = feed(page, *table, view);
    ASSERT_EQ(fed, "") << page.lastError();
    std::this_thread::sleep_for(seconds(1));
    ASSERT_TRUE(page.evaluate("window.poolMeter.reset()", seconds(5))) << page.lastError();
    std::this_thread::sleep_for(seconds(5));
    const auto read = page.evaluate("window.poolMeter.read()", seconds(5));
    ASSERT_TRUE(read && read->is_object()) << page.lastError();
    const auto mode = page.evaluate("window.poolTest.status().mode || 'full'", seconds(5));
    std::cout << "page-meter " << c.name << " mode " << (mode ? mode->dump() : "?") << " "
              << read->dump() << std::endl;
    ::testing::Test::RecordProperty(c.name, read->dump());
    if (shots) {
      const std::string png = page.screenshot(seconds(20));
      std::filesystem::create_directories(shots);
      std::ofstream(std::string(shots) + "/" + (label ? label : "page") + "-" + c.name + ".png",
                    std::ios::binary)
          << png;
    }
  }
}

}  // namespace
}  // namespace pool::client::test
