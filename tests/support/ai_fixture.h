// Test helpers for the bot's AI: the 9-ft table loaded once, layouts from ball lists, states.
#pragma once

#include <gtest/gtest.h>

#include <initializer_list>
#include <memory>
#include <utility>
#include <vector>

#include "client/bot/ai/shot_planner.h"
#include "client/bot/ai/table_view.h"
#include "physics/ball.h"
#include "rules/game_state.h"

namespace pool::bot::test {

/// The wpa-9ft table, loaded once per test program.
inline const TableView& nineFoot() {
  static const std::unique_ptr<TableView> view = [] {
    auto loaded = loadTableView("wpa-9ft");
    if (!loaded) throw std::runtime_error(loaded.error());
    return std::make_unique<TableView>(std::move(*loaded));
  }();
  return *view;
}

/// A ball at rest at (x, y) on the slate.
inline physics::Ball resting(int id, double x, double y) {
  physics::Ball b;
  b.id = id;
  b.pos = physics::Vec3(x, y, nineFoot().radius());
  return b;
}

/// A ball already pocketed (kept in the layout, as MatchState lists them).
inline physics::Ball pocketed(int id) {
  physics::Ball b;
  b.id = id;
  b.state = physics::MotionState::Pocketed;
  b.pos = physics::Vec3(0, 0, -0.2);
  return b;
}

/// A layout of the given balls plus every other id pocketed.
inline std::vector<physics::Ball> layout(std::initializer_list<physics::Ball> on_table) {
  std::vector<physics::Ball> balls(16);
  for (int id = 0; id < 16; ++id) balls[static_cast<std::size_t>(id)] = pocketed(id);
  for (const auto& b : on_table) balls[static_cast<std::size_t>(b.id)] = b;
  return balls;
}

/// Seat 0 to shoot with solids (seat 1 stripes), no ball in hand.
inline rules::GameState solidsToShoot() {
  rules::GameState state;
  state.phase = rules::Phase::Assigned;
  state.shooter = 0;
  state.groups = {rules::Group::Solids, rules::Group::Stripes};
  state.ball_in_hand = rules::BallInHand::None;
  return state;
}

/// A point on the line from the mouth of pocket `name` back through the table, `distance` m from
/// the mouth.
inline Vec2 onPocketLine(const std::string& name, const Vec2& toward, double distance) {
  const auto& view = nineFoot();
  const Vec2 mouth = view.pockets[static_cast<std::size_t>(pocketIndex(view, name))].mouth;
  return mouth + (toward - mouth).normalized() * distance;
}

}  // namespace pool::bot::test
