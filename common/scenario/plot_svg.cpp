// The physics lab's top-down plot: the table to scale, every ball's path, start, end and events.
#include <algorithm>

#include "scenario/ball_style.h"
#include "scenario/plot_table.h"
#include "scenario/scenario.h"
#include "scenario/svg_canvas.h"

namespace pool::scenario {
namespace {

using physics::Vec2;

constexpr double kScale = 400.0;  // px per metre
constexpr double kMargin = 20.0;  // px around the rails

SvgView makeView(const table::TableSpec& spec, const table::TableGeometry& geometry) {
  const Eigen::Vector2d half = tableOuterHalfSize(spec, geometry);
  SvgView view;
  view.scale = kScale;
  view.width = 2.0 * (half.x() * kScale + kMargin);
  view.height = 2.0 * (half.y() * kScale + kMargin);
  view.origin = {0.5 * view.width, 0.5 * view.height};
  return view;
}

const physics::Ball* findBall(const std::vector<physics::Ball>& balls, int id) {
  const auto it =
      std::find_if(balls.begin(), balls.end(), [id](const auto& b) { return b.id == id; });
  return it == balls.end() ? nullptr : &*it;
}

// Where a ball ends in the picture: its final position, or where it left the table.
Vec2 endPoint(int id, const Vec2& fallback, const physics::ShotOutcome& outcome) {
  const physics::Ball* last = findBall(outcome.balls, id);
  if (last != nullptr && physics::onTable(last->state)) return last->pos.head<2>();
  for (auto e = outcome.events.rbegin(); e != outcome.events.rend(); ++e) {
    const bool leaves =
        e->type == physics::EventType::Pocket || e->type == physics::EventType::OffTable;
    if (leaves && e->ball_a == id) return e->pos.head<2>();
  }
  return fallback;
}

// The ball's path in pixels: start, every sample while on the table, end; repeated points dropped.
std::vector<Vec2> pathPx(const SvgView& view, const physics::Ball& start,
                         const physics::ShotOutcome& outcome) {
  std::vector<Vec2> table_pts = {start.pos.head<2>()};
  for (const auto& sample : outcome.trajectory) {
    const physics::Ball* b = findBall(sample.balls, start.id);
    if (b == nullptr || !physics::onTable(b->state)) break;
    table_pts.push_back(b->pos.head<2>());
  }
  table_pts.push_back(endPoint(start.id, table_pts.back(), outcome));
  std::vector<Vec2> out;
  for (const auto& p : table_pts) {
    const Vec2 q = view.toPx(p);
    if (out.empty() || px(q.x()) != px(out.back().x()) || px(q.y()) != px(out.back().y()))
      out.push_back(q);
  }
  return out;
}

std::string drawPath(const std::vector<Vec2>& pts, int id, const table::TableSpec& spec) {
  const BallStyle style = ballStyle(id, spec);
  const std::string dash = style.striped ? " stroke-dasharray=\"7 4\"" : "";
  const std::string common = "fill=\"none\" stroke-linejoin=\"round\" stroke-linecap=\"round\"";
  // A dark underlay keeps light paths (the cue ball's, the yellow) visible on the cloth.
  return svgPolyline(pts, "class=\"path-outline\" " + common +
                              " stroke=\"#0a1a10\" stroke-opacity=\"0.7\" stroke-width=\"4\"") +
         svgPolyline(pts, "class=\"path\" data-ball=\"" + std::to_string(id) + "\" " + common +
                              " stroke=\"" + style.colour + "\" stroke-width=\"2\"" + dash);
}

// A ball seen from above, radius R to scale, with its number on a white disc.
std::string drawBall(const SvgView& view, const Vec2& at, int id, double radius,
                     const table::TableSpec& spec) {
  const BallStyle style = ballStyle(id, spec);
  const Vec2 c = view.toPx(at);
  const double r = radius * view.scale;
  if (style.cue) return svgCircle(c, r, "fill=\"#ffffff\" stroke=\"#222222\" stroke-width=\"1.5\"");
  std::string s =
      style.striped
          ? svgCircle(c, 0.72 * r,
                      "fill=\"#ffffff\" stroke=\"" + style.colour + "\" stroke-width=\"" +
                          px(0.56 * r) + "\"") +
                svgCircle(c, r, "fill=\"none\" stroke=\"#222222\" stroke-width=\"0.8\"")
          : svgCircle(c, r,
                      "fill=\"" + style.colour + "\" stroke=\"#222222\" stroke-width=\"0.8\"") +
                svgCircle(c, 0.45 * r, "fill=\"#ffffff\"");
  return s + "<text x=\"" + px(c.x()) + "\" y=\"" + px(c.y() + 3.0) +
         "\" font-size=\"8\" text-anchor=\"middle\" fill=\"#000000\">" + std::to_string(id) +
         "</text>\n";
}

std::string drawEvent(const SvgView& view, const physics::Event& e) {
  const Vec2 c = view.toPx(e.pos.head<2>());
  if (e.type == physics::EventType::BallBall) {
    const std::string attrs = "class=\"event ball_ball\" stroke=\"#ffffff\" stroke-width=\"1.5\"";
    return svgLine(c + Vec2(-3, -3), c + Vec2(3, 3), attrs) +
           svgLine(c + Vec2(-3, 3), c + Vec2(3, -3), attrs);
  }
  if (e.type == physics::EventType::BallCushion) {
    return svgCircle(
        c, 3.5,
        "class=\"event ball_cushion\" fill=\"none\" stroke=\"#ffffff\" stroke-width=\"1.2\"");
  }
  return "";
}

std::string svgHeader(const SvgView& view, const std::string& table_name) {
  const std::string w = px(view.width);
  const std::string h = px(view.height);
  return "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" + w + "\" height=\"" + h +
         "\" viewBox=\"0 0 " + w + " " + h +
         "\" font-family=\"sans-serif\">\n<title>pool-sim: " + table_name +
         ", 1 m = " + px(view.scale) +
         " px</title>\n<rect class=\"background\" width=\"100%\" height=\"100%\" "
         "fill=\"#f4f1ea\"/>\n";
}

}  // namespace

std::string plotSvg(const Scenario& scenario, const physics::ShotOutcome& outcome) {
  const SvgView view = makeView(scenario.spec, scenario.geometry);
  const double r = scenario.spec.params.ball_radius;
  std::string starts, paths, ends, pocketed, events;
  for (const auto& ball : scenario.balls) {
    const std::vector<Vec2> pts = pathPx(view, ball, outcome);
    starts += drawBall(view, ball.pos.head<2>(), ball.id, r, scenario.spec);
    if (pts.size() > 1) paths += drawPath(pts, ball.id, scenario.spec);
    const physics::Ball* last = findBall(outcome.balls, ball.id);
    const bool on_table = last == nullptr || physics::onTable(last->state);
    (on_table ? ends : pocketed) +=
        drawBall(view, endPoint(ball.id, ball.pos.head<2>(), outcome), ball.id, r, scenario.spec);
  }
  for (const auto& e : outcome.events) events += drawEvent(view, e);
  return svgHeader(view, scenario.spec.name) + drawTable(view, scenario.spec, scenario.geometry) +
         "<g class=\"start\" opacity=\"0.35\">\n" + starts + "</g>\n<g class=\"paths\">\n" + paths +
         "</g>\n<g class=\"end pocketed\" opacity=\"0.5\">\n" + pocketed +
         "</g>\n<g class=\"end\">\n" + ends + "</g>\n<g class=\"events\">\n" + events +
         "</g>\n</svg>\n";
}

}  // namespace pool::scenario
