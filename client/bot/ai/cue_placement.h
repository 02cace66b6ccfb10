// Ball in hand: where to put the cue ball for a pot (behind the head string when the rules say
// so), every spot checked with the rules' placement check.
#pragma once

#include <vector>

#include "client/bot/ai/plan_context.h"
#include "client/bot/ai/pot_search.h"

namespace pool::bot {

/// True when the cue ball may be placed at `at` with the shooter's ball in hand.
bool placementLegal(const PlanContext& context, const Vec2& at);

/// Pot candidates with the cue ball placed: spots behind each ball's ghost point on its line to a
/// pocket (straight and slightly angled), and, behind the head string, a grid of spots in the
/// kitchen. Every spot is legal; easiest first.
std::vector<PotCandidate> potsFromHand(const PlanContext& context);

/// Legal spots for the cue ball with nothing better to do (a safety from hand): the head spot
/// area behind the head string, or the middle of the table.
std::vector<Vec2> restingSpots(const PlanContext& context);

/// `context.balls` without the cue ball (the table as the placement sees it).
std::vector<physics::Ball> withoutCueBall(const std::vector<physics::Ball>& balls);

}  // namespace pool::bot
