// The levels' noise and planning effort.
#include "client/bot/ai/bot_level.h"

#include <array>

namespace pool::bot {
namespace {

struct LevelRow {
  Level level;
  const char* name;
  double noise_factor;
  int samples;
  int max_runs;  ///< physics trials a turn, at most
  LookAhead look_ahead;
  PotBreadth breadth;
};

constexpr std::array<LevelRow, 4> kLevels{{
    {Level::Beginner, "beginner", 12.0, 0, 320, LookAhead::NextShot, {}},
    {Level::Club, "club", 5.0, 8, 320, LookAhead::NextShot, {}},
    {Level::League, "league", 2.2, 16, 2000, LookAhead::TwoShots, {12, 24, 12, true}},
    {Level::Pro, "pro", 1.0, 48, 5000, LookAhead::TwoShots, {16, 48, 16, true}},
}};

const LevelRow& rowOf(Level level) {
  return kLevels[static_cast<std::size_t>(level)];
}

}  // namespace

const char* toString(Level level) {
  return rowOf(level).name;
}

std::vector<std::string> levelNames() {
  std::vector<std::string> names;
  for (const auto& row : kLevels) names.emplace_back(row.name);
  return names;
}

std::optional<Level> levelFromString(std::string_view name) {
  for (const auto& row : kLevels) {
    if (name == row.name) return row.level;
  }
  return std::nullopt;
}

double noiseFactor(Level level) {
  return rowOf(level).noise_factor;
}

ExecutionNoise levelNoise(Level level, double ball_radius) {
  ExecutionNoise noise = olympiadNoise(ball_radius);
  const double k = noiseFactor(level);
  noise.yaw *= k;
  noise.elevation *= k;
  noise.speed *= k;
  noise.tip *= k;
  return noise;
}

PlannerOptions plannerOptionsFor(Level level, double ball_radius) {
  PlannerOptions options;
  options.noise = levelNoise(level, ball_radius);
  options.samples = rowOf(level).samples;
  options.max_runs = rowOf(level).max_runs;
  options.look_ahead = rowOf(level).look_ahead;
  options.breadth = rowOf(level).breadth;
  return options;
}

}  // namespace pool::bot
