// Playing levels a player can tell apart: each an execution noise and a planning effort.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "client/bot/ai/execution_noise.h"
#include "client/bot/ai/shot_planner.h"

namespace pool::bot {

enum class Level : std::uint8_t { Beginner, Club, League, Pro };

inline constexpr Level kDefaultLevel = Level::Club;

/// "beginner", "club", "league", "pro".
const char* toString(Level level);
/// Every level's name, weakest first: the choices a command line offers.
std::vector<std::string> levelNames();
/// The level named `name`; none for any other text.
std::optional<Level> levelFromString(std::string_view name);

/// How many times the olympiad noise (olympiadNoise) a level's stroke carries: pro 1, league 2.2,
/// club 5, beginner 12 (spread so that each level wins at least 70 % of the racks against the one
/// below it: bot_bench's BM_BotHeadToHead, 200 racks a pair).
double noiseFactor(Level level);

/// A level's execution noise on a table with balls of `ball_radius` (m).
ExecutionNoise levelNoise(Level level, double ball_radius);

/// How a level plans: it judges its shortlisted pots under its own noise, with more samples and a
/// wider search the stronger it is; a beginner judges each by one exact trial. Club: 10 lines of
/// 12 strokes, its best 8 pots sampled 8 times. League: 12 lines of 24 strokes, 12 pots sampled 16
/// times, leaves graded two shots ahead (LookAhead::TwoShots). Pro: 16 lines of 36 strokes, 16
/// pots sampled 48 times, two shots ahead, up to 5000 physics trials a turn.
PlannerOptions plannerOptionsFor(Level level, double ball_radius);

}  // namespace pool::bot
