// A match's settings: names, checks and a one-line summary.
#include "protocol/match_settings.h"

#include <algorithm>
#include <cmath>

namespace pool::protocol {

const char* toString(BreakOrder order) {
  switch (order) {
    case BreakOrder::Alternate:
      return "alternate";
    case BreakOrder::Winner:
      return "winner";
  }
  return "unknown";
}

std::optional<BreakOrder> breakOrderOf(std::string_view name) {
  if (name == "alternate") return BreakOrder::Alternate;
  if (name == "winner") return BreakOrder::Winner;
  return std::nullopt;
}

double MatchSettings::warningAt() const {
  return std::min(kShotClockWarning, shot_clock / 3.0);
}

Check<> checkSettings(const MatchSettings& s) {
  const auto games = rules::allGames();
  if (std::none_of(games.begin(), games.end(), [&](const auto& g) { return g.game == s.game; })) {
    return Check<>::refuse("bad_game",
                           "game: must be 8-ball, 9-ball, 10-ball, three-cushion or snooker");
  }
  if (s.race_to < 1 || s.race_to > kMaxRace) {
    return Check<>::refuse("bad_race", "race: must be 1 to " + std::to_string(kMaxRace) + " racks");
  }
  if (s.game == rules::Game::ThreeCushion && (s.points < 1 || s.points > kMaxPoints)) {
    return Check<>::refuse("bad_points",
                           "points: must be 1 to " + std::to_string(kMaxPoints) + " points");
  }
  if (s.breaks != BreakOrder::Alternate && s.breaks != BreakOrder::Winner) {
    return Check<>::refuse("bad_breaks", "breaks: must be alternate or winner");
  }
  if (!std::isfinite(s.shot_clock) ||
      (s.shot_clock != 0.0 && (s.shot_clock < kMinShotClock || s.shot_clock > kMaxShotClock))) {
    return Check<>::refuse("bad_shot_clock",
                           "shot clock: must be off (0) or " +
                               std::to_string(static_cast<int>(kMinShotClock)) + " to " +
                               std::to_string(static_cast<int>(kMaxShotClock)) + " s");
  }
  if (s.practice && (s.race_to != 1 || s.shot_clock != 0.0)) {
    return Check<>::refuse("bad_practice",
                           "practice: a practice table has no race and no shot clock");
  }
  return Check<>::pass();
}

std::string describe(const MatchSettings& s) {
  if (s.practice) return std::string("practice, ") + rules::toString(s.game) + " rack";
  std::string text = std::string(rules::toString(s.game));
  if (s.game == rules::Game::ThreeCushion) text += ", " + std::to_string(s.points) + " points";
  text += ", race to " + std::to_string(s.race_to) + ", " + toString(s.breaks) + " breaks";
  if (!s.clockOn()) return text + ", no shot clock";
  const long seconds = std::lround(s.shot_clock);
  return text + ", shot clock " + std::to_string(seconds) + " s";
}

}  // namespace pool::protocol
