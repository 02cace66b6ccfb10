// Distils a checked event log into the facts a referee reads.
#include "rules/shot_facts.h"

#include <algorithm>

#include "rules/ball_groups.h"
#include "rules/log_check.h"

namespace pool::rules {
namespace {

using physics::Event;
using physics::EventType;

bool contains(const std::vector<int>& ids, int id) {
  return std::find(ids.begin(), ids.end(), id) != ids.end();
}

// The index of the cue ball's first contact with another ball, or the log's size.
std::size_t firstContactIndex(const physics::EventLog& events) {
  for (std::size_t i = 0; i < events.size(); ++i) {
    const Event& e = events[i];
    if (e.type == EventType::BallBall && (e.ball_a == 0 || e.ball_b == 0)) return i;
  }
  return events.size();
}

// Events carry ball_a's centre; only those of the cue ball tell where it was.
bool cueSeenPast(const physics::EventLog& events, std::size_t last, double head_string_x) {
  for (std::size_t i = 1; i <= last && i < events.size(); ++i) {
    const Event& e = events[i];
    if (e.ball_a == physics::kCueBall && e.pos.x() >= head_string_x) return true;
  }
  return false;
}

void addContactFacts(const physics::EventLog& events, double head_string_x, ShotFacts& facts) {
  std::size_t first = firstContactIndex(events);
  facts.cue_crossed_head_string = cueSeenPast(events, first, head_string_x);
  if (first == events.size()) return;
  const Event& contact = events[first];
  facts.first_contact = contact.ball_a == 0 ? contact.ball_b : contact.ball_a;
  for (std::size_t i = first; i < events.size(); ++i) {
    if (events[i].type == EventType::BallCushion) facts.cushion_after_contact = true;
  }
}

void addEventFacts(const Event& e, ShotFacts& facts) {
  if (e.type == EventType::Pocket) facts.pocketed.push_back({e.ball_a, e.where, e.t});
  if (e.type == EventType::OffTable) facts.off_table.push_back(e.ball_a);
  if (e.type == EventType::BallCushion && isObjectBall(e.ball_a) &&
      !contains(facts.cushioned, e.ball_a)) {
    facts.cushioned.push_back(e.ball_a);
  }
}

// A ball the watchdog re-spotted that ends off the table was removed by it.
void addRemoved(const Shot& shot, ShotFacts& facts) {
  for (const Event& e : shot.events) {
    if (e.type != EventType::Respot || contains(facts.removed, e.ball_a)) continue;
    if (facts.isPocketed(e.ball_a) || facts.isOffTable(e.ball_a)) continue;
    for (const auto& b : shot.after) {
      if (b.id == e.ball_a && !physics::onTable(b.state)) facts.removed.push_back(b.id);
    }
  }
}

}  // namespace

bool ShotFacts::isPocketed(int id) const {
  return std::any_of(pocketed.begin(), pocketed.end(),
                     [id](const Pocketing& p) { return p.id == id; });
}

bool ShotFacts::isOffTable(int id) const {
  return contains(off_table, id);
}
bool ShotFacts::isRemoved(int id) const {
  return contains(removed, id);
}

std::string ShotFacts::pocketOf(int id) const {
  for (const auto& p : pocketed) {
    if (p.id == id) return p.pocket;
  }
  return "";
}

std::vector<int> ShotFacts::objectBallsPocketed() const {
  std::vector<int> ids;
  for (const auto& p : pocketed) {
    if (isObjectBall(p.id)) ids.push_back(p.id);
  }
  return ids;
}

std::vector<int> ShotFacts::objectBallsOffTable() const {
  std::vector<int> ids;
  for (int id : off_table) {
    if (isObjectBall(id)) ids.push_back(id);
  }
  return ids;
}

Result<ShotFacts> distilShot(const Shot& shot, double head_string_x) {
  if (auto checked = checkShot(shot); !checked) return Result<ShotFacts>::fail(checked.error());
  ShotFacts facts;
  addContactFacts(shot.events, head_string_x, facts);
  for (const Event& e : shot.events) addEventFacts(e, facts);
  addRemoved(shot, facts);
  return Result<ShotFacts>::ok(std::move(facts));
}

}  // namespace pool::rules
