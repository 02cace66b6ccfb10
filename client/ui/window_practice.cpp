// The practice keys, scenario files and physics pane of the window.
#include "client/ui/window_practice.h"

#include <imgui.h>

#include <fstream>
#include <sstream>

#include "client/app/practice_layout.h"
#include "client/bot/ai/bot_level.h"
#include "client/bot/ai/break_shot.h"
#include "client/bot/ai/shot_planner.h"
#include "client/bot/shot_command.h"
#include "scenario/scenario.h"
#include "scenario/scenario_write.h"

namespace pool::ui {
namespace {

using protocol::PracticeAction;
using protocol::PracticeRequest;

PracticeRequest command(PracticeAction action) {
  PracticeRequest r;
  r.action = action;
  return r;
}

PracticeRequest rack(int game) {
  PracticeRequest r = command(PracticeAction::Rack);
  r.rack = game;
  return r;
}

/// The slider range of each coefficient (the server checks the exact ranges).
struct Range {
  float low;
  float high;
};
constexpr std::array<Range, protocol::kPracticeCoefficients.size()> kRanges{{
    {0.01f, 1.0f},   // u_s
    {0.001f, 0.1f},  // u_r
    {0.5f, 50.0f},   // spin_decel
    {0.5f, 1.0f},    // e_b
    {0.3f, 1.0f},    // e_c
    {0.0f, 1.0f},    // u_c
    {0.0f, 1.0f},    // e_slate
}};

}  // namespace

PracticeDesk::PracticeDesk(const game::LoadedTable& view, std::string scenario_file)
    : view_(view), file_(std::move(scenario_file)) {}

PracticeOutcome PracticeDesk::key(app::Key key, app::MatchSession& session,
                                  app::Controls& controls) {
  PracticeOutcome out;
  if (!session.practiceTable()) return out;
  // At snooker's or the carom table every rack key racks that table's game.
  const rules::Game game = session.view()->settings.game;
  switch (key) {
    case app::Key::U:
      queue(command(PracticeAction::Undo));
      break;
    case app::Key::Y:
      queue(command(PracticeAction::Again));
      break;
    case app::Key::J:
      if (session.lastShot()) {
        out.shot = *session.lastShot();
        out.shot->cue_ball_at.reset();  // from the table as it is
      } else {
        out.note = app::SessionNote{"no shot to play yet", true};
      }
      break;
    case app::Key::H:
      out.note = advise(session, controls);
      break;
    case app::Key::Num8:
      queue(rack(app::practiceRack(game, 8)));
      break;
    case app::Key::Num9:
      queue(rack(app::practiceRack(game, 9)));
      break;
    case app::Key::Num0:
      queue(rack(app::practiceRack(game, 10)));
      break;
    case app::Key::Backspace:
      queue(rack(0));
      break;
    case app::Key::F5:
      out.note = save(session);
      break;
    case app::Key::F6:
      out.note = load(session);
      break;
    case app::Key::F7:
      pane_open_ = !pane_open_;
      editing_.reset();
      break;
    default:
      break;
  }
  return out;
}

void PracticeDesk::moveBall(const client::MatchView& view, int id, const Eigen::Vector2d& at) {
  PracticeRequest layout = command(PracticeAction::Layout);
  layout.balls = app::layoutWithMove(view.balls, id, at, view_.context);
  queue(std::move(layout));
}

std::optional<app::SessionNote> PracticeDesk::step(app::MatchSession& session) {
  if (waiting_.empty() || session.inMotion() || session.localShooter() < 0) return std::nullopt;
  PracticeRequest next = std::move(waiting_.front());
  waiting_.pop_front();
  const std::string what = protocol::toString(next.action);
  if (auto sent = session.practice(std::move(next)); !sent) {
    waiting_.clear();
    return app::SessionNote{"practice " + what + ": " + sent.error(), true};
  }
  return app::SessionNote{"practice " + what + " sent", false};
}

std::string PracticeDesk::scenarioOf(const client::MatchView& view,
                                     const protocol::ShotRequest& shot, const std::string& table) {
  scenario::ScenarioSource source;
  source.table = table;
  for (std::size_t i = 0; i < protocol::kPracticeCoefficients.size(); ++i) {
    source.params.emplace_back(protocol::kPracticeCoefficients[i], view.coefficients[i]);
  }
  source.balls = view.balls;
  if (shot.cue_ball_at) {
    for (auto& b : source.balls) {
      if (b.id != physics::kCueBall) continue;
      // Only x and y go into the file: the ball rests on the slate there.
      b = physics::restingBall(physics::kCueBall, *shot.cue_ball_at, b.pos.z());
    }
  }
  source.shot = shot.cue;
  return scenario::scenarioJson(source);
}

app::SessionNote PracticeDesk::save(const app::MatchSession& session) const {
  const client::MatchView* v = session.view();
  if (!v || !session.lastShot()) return {"save: no shot to save yet (shoot first)", true};
  std::ofstream out(file_);
  out << scenarioOf(*v, *session.lastShot(), view_.spec.name);
  if (!out) return {"save: cannot write " + file_, true};
  return {"saved the table and the last shot to " + file_ + " (pool-sim " + file_ + ")", false};
}

app::SessionNote PracticeDesk::load(app::MatchSession& session) {
  auto loaded = scenario::loadScenario(file_);
  if (!loaded) return {"load " + file_ + ": " + loaded.error(), true};
  PracticeRequest layout = command(PracticeAction::Layout);
  for (const auto& b : loaded->balls) {
    if (physics::onTable(b.state)) layout.balls.push_back({b.id, b.pos.x(), b.pos.y()});
  }
  queue(std::move(layout));
  const auto coefficients = protocol::coefficientsOf(loaded->spec.params);
  const client::MatchView* v = session.view();
  if (!v || v->coefficients != coefficients) {
    PracticeRequest physics = command(PracticeAction::Physics);
    physics.coefficients = coefficients;
    queue(std::move(physics));
  }
  protocol::ShotRequest shot;
  shot.cue = loaded->shot;
  session.setLastShot(shot);
  return {"loaded " + file_ + ": J plays its shot", false};
}

app::SessionNote PracticeDesk::advise(const app::MatchSession& session,
                                      app::Controls& controls) const {
  const client::MatchView* v = session.view();
  if (!v || controls.mode() != app::ControlMode::Aiming)
    return {"the bot advises while you aim", true};
  bot::TableView table = bot::tableViewOf(view_);
  table.rules.game = v->settings.game;
  // The advice of the strongest level: it weighs each pot by how often a professional's stroke
  // would make it, and the leave by the next pot's chances (the flawless planner would call any
  // pot that exists, however thin).
  bot::ShotPlanner planner(table, bot::plannerOptionsFor(bot::Level::Pro, table.radius()));
  // A fresh rack wants a break, whatever the practice table's own state says.
  const rules::GameState state = bot::looksRacked(table, v->balls)
                                     ? rules::newRack(std::max(0, v->shooter))
                                     : client::gameStateOf(*v);
  const bot::PlannedShot plan = planner.plan(v->balls, state);
  if (plan.cue_ball_at) controls.moveCueBall(*plan.cue_ball_at);
  controls.setYaw(plan.cue.yaw);
  return {"the pro bot would play: " + bot::describe(plan), false};
}

void PracticeDesk::drawPhysicsPane(const client::MatchView& view, std::vector<std::string>& texts) {
  if (!pane_open_ || !view.settings.practice) return;
  if (!editing_) editing_ = view.coefficients;
  ImGui::SetNextWindowPos(ImVec2(10, 300), ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(1.0f);  // the panes beneath do not show through
  ImGui::Begin("Physics (this table)", &pane_open_, ImGuiWindowFlags_AlwaysAutoResize);
  texts.emplace_back(view.standard_physics ? "physics: standard" : "physics: not standard");
  ImGui::TextUnformatted(view.standard_physics ? "standard coefficients" : "not a standard table");
  for (std::size_t i = 0; i < editing_->size(); ++i) {
    float value = static_cast<float>((*editing_)[i]);
    const std::string name(protocol::kPracticeCoefficients[i]);
    if (ImGui::SliderFloat(name.c_str(), &value, kRanges[i].low, kRanges[i].high, "%.4f")) {
      (*editing_)[i] = value;
    }
    texts.push_back(name);
  }
  if (ImGui::Button("Apply")) {
    PracticeRequest r = command(PracticeAction::Physics);
    r.coefficients = *editing_;
    queue(std::move(r));
  }
  ImGui::SameLine();
  if (ImGui::Button("Standard")) {
    editing_ = protocol::coefficientsOf(view_.spec.params);
    PracticeRequest r = command(PracticeAction::Physics);
    r.coefficients = *editing_;
    queue(std::move(r));
  }
  ImGui::End();
}

}  // namespace pool::ui
