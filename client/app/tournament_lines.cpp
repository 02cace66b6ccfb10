// A tournament's line, bracket and entrants in words.
#include "client/app/tournament_lines.h"

#include <algorithm>
#include <numeric>

namespace pool::app {
namespace {

const char* formatWords(protocol::TournamentFormat format) {
  switch (format) {
    case protocol::TournamentFormat::SingleElimination:
      return "single elimination";
    case protocol::TournamentFormat::DoubleElimination:
      return "double elimination";
    case protocol::TournamentFormat::RoundRobin:
      return "round robin";
  }
  return "";
}

std::string nameOf(const protocol::TournamentView& t, int i) {
  return i >= 0 && i < static_cast<int>(t.entrants.size())
             ? t.entrants[static_cast<std::size_t>(i)].name
             : "to come";
}

}  // namespace

std::string tournamentLine(const protocol::TournamentView& t) {
  std::string where =
      std::to_string(t.entrants.size()) + "/" + std::to_string(t.capacity) + " entered";
  if (t.phase == protocol::TournamentPhase::Running) {
    const auto decided = std::count_if(t.matches.begin(), t.matches.end(),
                                       [](const auto& m) { return m.state == 3; });
    where = "running, " + std::to_string(decided) + " of " + std::to_string(t.matches.size()) +
            " matches played";
  } else if (t.phase == protocol::TournamentPhase::Finished) {
    where = "won by " + nameOf(t, t.champion);
  } else if (t.phase == protocol::TournamentPhase::Cancelled) {
    where = "cancelled";
  }
  return t.name + ": " + rules::toString(t.game) + ", " + formatWords(t.format) + ", race to " +
         std::to_string(t.race_to) + (t.handicap ? ", handicapped" : "") + " - " + where;
}

std::vector<BracketLine> bracketLines(const protocol::TournamentView& t) {
  std::vector<BracketLine> out;
  for (const auto& m : t.matches) {
    std::string pair = m.round + ": " + nameOf(t, m.a) + " v " + nameOf(t, m.b);
    // A handicap: the racks one of them started with.
    if (m.spot_a > 0) pair += " (" + nameOf(t, m.a) + " +" + std::to_string(m.spot_a) + ")";
    if (m.spot_b > 0) pair += " (" + nameOf(t, m.b) + " +" + std::to_string(m.spot_b) + ")";
    if (m.state == 3) {
      const std::string score = m.forfeit ? "by forfeit"
                                          : std::to_string(std::max(m.racks_a, m.racks_b)) + "-" +
                                                std::to_string(std::min(m.racks_a, m.racks_b));
      out.push_back({pair + " - " + nameOf(t, m.winner) + " won " + score, m.match, false});
    } else if (m.state == 2) {
      out.push_back({pair + " - in play at " + m.match, m.match, true});
    } else {
      out.push_back({pair + " - " + (m.state == 1 ? "next" : "waiting"), {}, false});
    }
  }
  return out;
}

std::vector<std::string> entrantLines(const protocol::TournamentView& t) {
  std::vector<std::size_t> order(t.entrants.size());
  std::iota(order.begin(), order.end(), 0);
  const bool seeded =
      std::any_of(t.entrants.begin(), t.entrants.end(), [](const auto& e) { return e.seed > 0; });
  if (seeded) {
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
      return t.entrants[a].seed < t.entrants[b].seed;
    });
  }
  std::vector<std::string> out;
  for (const std::size_t i : order) {
    const auto& e = t.entrants[i];
    std::string line = (e.seed > 0 ? std::to_string(e.seed) + ". " : std::string()) + e.name +
                       " (" + std::to_string(e.rating) + ")";
    if (e.place > 0 && t.phase == protocol::TournamentPhase::Finished) {
      line += ", place " + std::to_string(e.place);
    }
    if (e.withdrawn) line += ", withdrawn";
    out.push_back(std::move(line));
  }
  return out;
}

}  // namespace pool::app
