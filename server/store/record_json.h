// JSON text of the match data the store keeps (balls, rules state, verdicts, events, commands).
#pragma once

#include <string>
#include <vector>

#include "physics/ball.h"
#include "physics/events.h"
#include "protocol/match_settings.h"
#include "protocol/shot_request.h"
#include "rules/game_state.h"
#include "rules/shot.h"
#include "rules/verdict.h"

namespace pool::store {

// Every double is written with enough digits to read back bit-identical. The readers throw
// StoreError (naming what failed) on text that does not hold what they expect.

std::string ballsJson(const std::vector<physics::Ball>& balls);
std::vector<physics::Ball> ballsFrom(const std::string& text);

/// A match's settings; "{}" (an older file) reads as the defaults (8-ball, one rack).
std::string settingsJson(const protocol::MatchSettings& settings);
protocol::MatchSettings settingsFrom(const std::string& text);

std::string gameJson(const rules::GameState& state);
rules::GameState gameFrom(const std::string& text);

std::string verdictJson(const rules::Verdict& verdict);
rules::Verdict verdictFrom(const std::string& text);

std::string eventsJson(const physics::EventLog& events);
physics::EventLog eventsFrom(const std::string& text);

std::string intentJson(const rules::Intent& intent);
rules::Intent intentFrom(const std::string& text);

std::string commandJson(const protocol::ShotRequest& command);
protocol::ShotRequest commandFrom(const std::string& text);

}  // namespace pool::store
