// The replay message pool-web sends a browser: a stored shot's frames, rebuilt from its layouts
// and events (client/app/shot_replay.h), with its facts and its pool-sim scenario.
#pragma once

#include <string>

#include "protocol/history.h"

namespace pool::web {

/// Frames a second of a replay sent to the page (it interpolates between them as between live
/// frames; a rebuilt path is straight or evenly curved between its events).
inline constexpr double kReplayHz = 30.0;

/// A found shot: {"type":"replay","found":true,"match","shot","shots","game","table","players":
/// [a,b],"seat","verdict","verdict_words","shoots","before":[balls],"after":[balls],"frames":
/// [{"t":s,"balls":[balls]}...],"scenario":"<the pool-sim scenario of the shot, JSON text>"}
/// (balls as ballsArray writes them). Not found: {"type":"replay","found":false,"match","shot",
/// "error"}, `shot` being the number asked for.
std::string replayJson(const protocol::HistoryShot& shot, std::uint32_t asked);

}  // namespace pool::web
