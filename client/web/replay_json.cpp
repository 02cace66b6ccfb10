// A stored shot as the page's replay message: its frames rebuilt from the stored log, never
// simulated again.
#include "client/web/replay_json.h"

#include <fmt/format.h>

#include <nlohmann/json.hpp>

#include "client/app/shot_replay.h"
#include "client/app/spoken.h"
#include "client/web/web_json.h"
#include "scenario/scenario_write.h"

namespace pool::web {

std::string replayJson(const protocol::HistoryShot& shot, std::uint32_t asked) {
  using nlohmann::json;
  if (!shot.found) {
    return json{{"type", "replay"},
                {"found", false},
                {"match", shot.match},
                {"shot", asked},
                {"error", shot.error}}
        .dump(-1, ' ', false, json::error_handler_t::replace);
  }
  const auto frames = app::replayFrames(shot.before, shot.events, shot.after, kReplayHz);
  std::string frames_text = "[";
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (i) frames_text += ',';
    fmt::format_to(std::back_inserter(frames_text), R"({{"t":{:.5f},"balls":{}}})", frames[i].t,
                   ballsArray(frames[i].balls));
  }
  frames_text += ']';
  scenario::ScenarioSource source;
  source.table = shot.table;
  source.balls = shot.before;
  source.shot = shot.cue;
  const json facts{{"type", "replay"},
                   {"found", true},
                   {"match", shot.match},
                   {"shot", shot.shot_number},
                   {"shots", shot.shots},
                   {"game", rules::toString(shot.game)},
                   {"table", shot.table},
                   {"players", shot.players},
                   {"seat", shot.seat},
                   {"verdict", shot.verdict_text},
                   {"verdict_words", app::spokenText(shot.verdict_text)},
                   {"shoots", shot.shoots},
                   // A scenario file strikes the cue ball: three-cushion's second player's shot
                   // (their own ball struck) has none to download.
                   {"scenario", shot.shoots && shot.cue.ball == physics::kCueBall
                                    ? scenario::scenarioJson(source)
                                    : std::string()}};
  std::string text = facts.dump(-1, ' ', false, json::error_handler_t::replace);
  text.pop_back();  // the closing brace: the balls and frames follow, written as the live ones
  fmt::format_to(std::back_inserter(text), R"(,"before":{},"after":{},"frames":{}}})",
                 ballsArray(shot.before), ballsArray(shot.after), frames_text);
  return text;
}

}  // namespace pool::web
