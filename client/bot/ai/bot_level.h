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

/// How many times the olympiad noise (olympiadNoise) a level's stroke carries: pro 1, league 2.5,
/// club 4.5, beginner 8 (spread so that each level wins at least 70 % of the racks against the one
/// below it: bot_bench's BM_BotHeadToHead, 200 racks a pair).
double noiseFactor(Level level);

/// A level's execution noise on a table with balls of `ball_radius` (m).
ExecutionNoise levelNoise(Level level, double ball_radius);

/// How a level plans: it judges its shortlisted pots under its own noise, with more samples the
/// stronger it is (league 12, club 8); a beginner judges each by one exact trial. The pro looks
/// widest and furthest: 16 lines of 36 strokes each, its best 16 pots sampled 48 times, up to
/// 5000 physics trials a turn, and each leave graded two shots ahead (LookAhead::TwoShots).
PlannerOptions plannerOptionsFor(Level level, double ball_radius);

}  // namespace pool::bot
