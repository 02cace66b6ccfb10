// The tournament facade: create, start, report, forfeit, cancel, champion and standings.
#include "server/tournament/tournament.h"

#include "server/tournament/bracket.h"
#include "server/tournament/round_robin.h"
#include "server/tournament/seeding.h"

#include <algorithm>
#include <utility>

namespace pool::tournament {
namespace {

std::string matchName(int match) {
  return "match " + std::to_string(match);
}

}  // namespace

Result<Tournament> Tournament::create(Format format, std::vector<Entrant> entrants,
                                      Options options) {
  if (const Check<> field = checkEntrants(entrants); !field) {
    return Result<Tournament>::fail(field.code(), field.error());
  }
  if (options.raceTo < 0) {
    return Result<Tournament>::fail("bad_options", "tournament options: raceTo is negative");
  }
  Tournament t;
  t.format_ = format;
  t.options_ = options;
  t.entrants_ = std::move(entrants);
  const std::vector<int> bySeed = seedOrder(t.entrants_);
  t.seeds_.assign(bySeed.size(), 0);
  for (std::size_t i = 0; i < bySeed.size(); ++i) t.seeds_[bySeed[i]] = static_cast<int>(i) + 1;
  switch (format) {
    case Format::SingleElimination:
      t.matches_ = buildSingleElimination(bySeed);
      break;
    case Format::DoubleElimination:
      t.matches_ = buildDoubleElimination(bySeed);
      break;
    case Format::RoundRobin:
      t.matches_ = buildRoundRobin(bySeed);
      break;
    default:
      return Result<Tournament>::fail("bad_options", "tournament options: unknown format");
  }
  t.withdrawn_.assign(t.entrants_.size(), false);
  return Result<Tournament>::ok(std::move(t));
}

Check<> Tournament::checkRunning(const char* call) const {
  if (cancelled_)
    return Check<>::refuse("over", std::string(call) + ": the tournament is cancelled");
  if (finished())
    return Check<>::refuse("over", std::string(call) + ": the tournament is finished");
  return Check<>::pass();
}

std::vector<int> Tournament::readyMatches() const {
  if (cancelled_ || finished()) return {};
  std::vector<bool> busy(entrants_.size(), false);
  for (const Match& m : matches_) {
    if (m.state == MatchState::InPlay) busy[m.a] = busy[m.b] = true;
  }
  std::vector<int> ready;
  for (const Match& m : matches_) {
    if (m.state == MatchState::Ready && !busy[m.a] && !busy[m.b]) ready.push_back(m.index);
  }
  return ready;
}

Check<> Tournament::start(int match) {
  if (Check<> running = checkRunning("start"); !running) return running;
  if (match < 0 || match >= static_cast<int>(matches_.size())) {
    return Check<>::refuse("unknown_match", "start: there is no " + matchName(match));
  }
  Match& m = matches_[match];
  switch (m.state) {
    case MatchState::Waiting:
      return Check<>::refuse("not_ready", "start: " + matchName(match) + " waits for an entrant");
    case MatchState::InPlay:
      return Check<>::refuse("in_play", "start: " + matchName(match) + " is already in play");
    case MatchState::Done:
      return Check<>::refuse("reported", "start: " + matchName(match) + " is already reported");
    case MatchState::Ready:
      break;
  }
  for (const Match& other : matches_) {
    if (other.state == MatchState::InPlay && (other.has(m.a) || other.has(m.b))) {
      return Check<>::refuse("entrant_busy", "start: an entrant of " + matchName(match) +
                                                 " is in play in " + matchName(other.index));
    }
  }
  m.state = MatchState::InPlay;
  log_.push_back({.kind = Event::Kind::Start, .match = match});
  return Check<>::pass();
}

Check<> Tournament::report(int match, int winner, int racksA, int racksB) {
  if (Check<> running = checkRunning("report"); !running) return running;
  if (match < 0 || match >= static_cast<int>(matches_.size())) {
    return Check<>::refuse("unknown_match", "report: there is no " + matchName(match));
  }
  const Match& m = matches_[match];
  if (m.state == MatchState::Done) {
    return Check<>::refuse("reported", "report: " + matchName(match) + " is already reported");
  }
  if (m.state != MatchState::InPlay) {
    return Check<>::refuse("not_in_play", "report: " + matchName(match) + " is not in play");
  }
  if (!m.has(winner)) {
    return Check<>::refuse("not_in_match", "report: entrant " + std::to_string(winner) +
                                               " does not play " + matchName(match));
  }
  const std::string score = std::to_string(racksA) + "-" + std::to_string(racksB);
  if (racksA < 0 || racksB < 0) {
    return Check<>::refuse("bad_racks", "report: racks " + score + " are negative");
  }
  const int won = winner == m.a ? racksA : racksB;
  const int lost = winner == m.a ? racksB : racksA;
  if (won <= lost) {
    return Check<>::refuse("bad_racks", "report: racks " + score + " do not put the winner ahead");
  }
  if (options_.raceTo > 0 && (won != options_.raceTo || lost >= options_.raceTo)) {
    return Check<>::refuse("bad_racks", "report: racks " + score + " are no score of a race to " +
                                            std::to_string(options_.raceTo));
  }
  decide(match, winner, racksA, racksB, false);
  log_.push_back({.kind = Event::Kind::Report,
                  .match = match,
                  .entrant = winner,
                  .racksA = racksA,
                  .racksB = racksB});
  settleForfeits();
  return Check<>::pass();
}

Result<std::vector<int>> Tournament::forfeit(int entrant) {
  using Answer = Result<std::vector<int>>;
  if (Check<> running = checkRunning("forfeit"); !running) {
    return Answer::fail(running.code(), running.error());
  }
  if (entrant < 0 || entrant >= static_cast<int>(entrants_.size())) {
    return Answer::fail("unknown_entrant",
                        "forfeit: there is no entrant " + std::to_string(entrant));
  }
  if (withdrawn_[entrant]) {
    return Answer::fail("withdrawn", "forfeit: entrant " + std::to_string(entrant) + " (" +
                                         entrants_[entrant].id + ") has already left");
  }
  withdrawn_[entrant] = true;
  log_.push_back({.kind = Event::Kind::Forfeit, .entrant = entrant});
  return Answer::ok(settleForfeits());
}

Result<std::vector<int>> Tournament::cancel() {
  using Answer = Result<std::vector<int>>;
  if (Check<> running = checkRunning("cancel"); !running) {
    return Answer::fail(running.code(), running.error());
  }
  std::vector<int> inPlay;
  for (const Match& m : matches_) {
    if (m.state == MatchState::InPlay) inPlay.push_back(m.index);
  }
  cancelled_ = true;
  log_.push_back({.kind = Event::Kind::Cancel});
  return Answer::ok(std::move(inPlay));
}

void Tournament::decide(int match, int winner, int racksA, int racksB, bool forfeit) {
  Match& m = matches_[match];
  m.state = MatchState::Done;
  m.winner = winner;
  m.racksA = racksA;
  m.racksB = racksB;
  m.forfeit = forfeit;
  const Match done = m;  // matches_ may grow below
  const auto place = [this](Slot slot, int entrant) {
    Match& next = matches_[slot.match];
    (slot.side == 0 ? next.a : next.b) = entrant;
    if (next.a >= 0 && next.b >= 0) next.state = MatchState::Ready;
  };
  if (done.winnerTo.match >= 0) place(done.winnerTo, winner);
  if (done.loserTo.match >= 0) place(done.loserTo, done.loser());
  if (format_ == Format::RoundRobin) {
    const bool allDone = std::all_of(matches_.begin(), matches_.end(),
                                     [](const Match& x) { return x.state == MatchState::Done; });
    if (allDone) champion_ = rankRoundRobin(matches_, seeds_).front();
    return;
  }
  if (done.winnerTo.match >= 0) return;
  if (done.kind == MatchKind::GrandFinal && winner == done.b) {
    Match reset;
    reset.index = static_cast<int>(matches_.size());
    reset.round = "GF reset";
    reset.kind = MatchKind::GrandFinalReset;
    reset.stage = done.stage;
    reset.a = done.a;
    reset.b = done.b;
    reset.state = MatchState::Ready;
    matches_.push_back(reset);
    return;
  }
  champion_ = winner;
}

std::vector<int> Tournament::settleForfeits() {
  std::vector<int> decided;
  for (bool again = true; again && !finished();) {
    again = false;
    for (std::size_t i = 0; i < matches_.size() && !finished(); ++i) {
      const Match& m = matches_[i];
      if (m.state != MatchState::Ready && m.state != MatchState::InPlay) continue;
      if (!withdrawn_[m.a] && !withdrawn_[m.b]) continue;
      const int winner = withdrawn_[m.a] && !withdrawn_[m.b] ? m.b : m.a;
      decide(static_cast<int>(i), winner, 0, 0, true);
      decided.push_back(static_cast<int>(i));
      again = true;
    }
  }
  return decided;
}

std::vector<Standing> Tournament::standings() const {
  return format_ == Format::RoundRobin ? roundRobinStandings(matches_, seeds_)
                                       : eliminationStandings(matches_, seeds_);
}

}  // namespace pool::tournament
