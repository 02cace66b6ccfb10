// JSON lines with nlohmann-json, one object a line, flushed at once.
#include "client/ui/window_log.h"

#include <iostream>
#include <nlohmann/json.hpp>

#include "scenario/cue_shot_json.h"

namespace pool::ui {
namespace {

void printLine(const nlohmann::json& line) {
  std::cout << line.dump() << '\n' << std::flush;
}

}  // namespace

void printShotLine(const std::string& match, int seat, std::uint32_t seq,
                   const protocol::ShotRequest& request) {
  nlohmann::json line = scenario::cueShotJson(request.cue);
  line["event"] = "shot";
  line["match"] = match;
  line["seat"] = seat;
  line["seq"] = seq;
  line["safety"] = request.safety;
  line["option"] = protocol::toString(request.option);
  if (request.called_ball) {
    line["called_ball"] = *request.called_ball;
    line["called_pocket"] = request.called_pocket;
  }
  if (request.cue_ball_at)
    line["cue_ball_at"] = {request.cue_ball_at->x(), request.cue_ball_at->y()};
  printLine(line);
}

void printNoteLine(const app::SessionNote& note) {
  printLine({{"event", "note"}, {"text", note.text}, {"problem", note.problem}});
}

void printHudLine(const std::vector<std::string>& texts) {
  printLine({{"event", "hud"}, {"texts", texts}});
}

void printDrawnLine(const DrawnFrame& f) {
  nlohmann::json line{{"event", "drawn"},         {"now", f.now},
                      {"moving", f.moving},       {"play_time", f.play_time},
                      {"aiming", f.aiming},       {"dragging", f.dragging},
                      {"replaying", f.replaying}, {"replay_time", f.replay_time},
                      {"quality", f.quality},     {"mouse", {f.mouse.x(), f.mouse.y()}},
                      {"view", f.view},           {"projection", f.projection},
                      {"width", f.width},         {"height", f.height}};
  line["shot"] = f.shot ? nlohmann::json(*f.shot) : nlohmann::json();
  if (f.cue) line["cue"] = {f.cue->x(), f.cue->y(), f.cue->z()};
  if (f.cue_px) line["cue_px"] = {f.cue_px->x(), f.cue_px->y()};
  if (f.cue_stick) {
    const CueStick& c = *f.cue_stick;
    line["cue_stick"] = {{"tip", {c.tip.x(), c.tip.y(), c.tip.z()}},
                         {"butt", {c.butt.x(), c.butt.y(), c.butt.z()}},
                         {"tip_px", {c.tip_px.x(), c.tip_px.y()}},
                         {"butt_px", {c.butt_px.x(), c.butt_px.y()}},
                         {"source", f.cue_source}};
  }
  if (f.live_aim) {
    const protocol::AimSample& a = *f.live_aim;
    line["live_aim"] = {{"seat", a.seat},
                        {"seq", a.seq},
                        {"shot_number", a.shot_number},
                        {"yaw", a.yaw},
                        {"tip_side", a.tip_side},
                        {"tip_height", a.tip_height},
                        {"elevation", a.elevation},
                        {"power", a.power},
                        {"stroke", a.stroke}};
  }
  line["aim_dropped"] = f.aim_dropped;
  if (!f.capture.empty()) line["capture"] = f.capture;
  if (f.stored) {
    nlohmann::json balls = nlohmann::json::array();
    for (const auto& b : f.stored->balls) {
      balls.push_back(
          {{"id", b.id}, {"on", physics::onTable(b.state)}, {"x", b.pos.x()}, {"y", b.pos.y()}});
    }
    line["stored"] = {{"match", f.stored->match},     {"shot", f.stored->shot},
                      {"shots", f.stored->shots},     {"time", f.stored->time},
                      {"at_rest", f.stored->at_rest}, {"balls", balls}};
  }
  printLine(line);
}

void ProgressLog::report(const app::MatchSession& session) {
  const client::MatchView* v = session.view();
  if (v && (!last_revision_ || *last_revision_ != v->revision)) {
    last_revision_ = v->revision;
    printLine({{"event", "state"},
               {"match", v->match},
               {"revision", v->revision},
               {"phase", client::toString(v->phase)},
               {"shot_number", v->shot_number},
               {"shooter", v->shooter}});
  }
  const auto shot = session.motionShot();
  if (shot && session.inMotion() && shot != last_motion_) {
    last_motion_ = shot;
    printLine({{"event", "motion"}, {"match", session.match()}, {"shot_number", *shot}});
  }
}

}  // namespace pool::ui
