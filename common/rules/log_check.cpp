// Refuses a shot whose event log or final balls contradict themselves or the table before the shot.
#include "rules/log_check.h"

#include <array>
#include <cmath>
#include <string>

#include "rules/table_context.h"

namespace pool::rules {
namespace {

using physics::Event;
using physics::EventType;
using physics::MotionState;

constexpr int kBalls = physics::kMaxBallId + 1;

/// What the log has said about one ball so far.
struct BallTrack {
  bool on_table = false;  ///< on the table before the shot
  bool moving = false;
  bool gone = false;  ///< pocketed or off the table
  bool respotted = false;
  EventType gone_by = EventType::Pocket;
};

std::string at(const Event& event) {
  return " at t=" + std::to_string(event.t);
}
std::string ball(int id) {
  return "ball " + std::to_string(id);
}
bool validId(int id) {
  return id >= 0 && id < kBalls;
}

// The rules do not link the physics library, so they name the final states themselves.
const char* stateName(MotionState state) {
  switch (state) {
    case MotionState::Pocketed:
      return "pocketed";
    case MotionState::OffTable:
      return "off the table";
    default:
      return "on the table";
  }
}

using Tracks = std::array<BallTrack, kBalls>;

// Balls before the shot: ids in range, each once, the cue ball on the table.
Result<Tracks> tracksBefore(const std::vector<physics::Ball>& before) {
  Tracks tracks{};
  std::array<bool, kBalls> seen{};
  for (const auto& b : before) {
    if (!validId(b.id))
      return Result<Tracks>::fail("balls before: id " + std::to_string(b.id) + " is not 0-15");
    if (seen[b.id]) return Result<Tracks>::fail("balls before: " + ball(b.id) + " is listed twice");
    seen[b.id] = true;
    tracks[b.id].on_table = physics::onTable(b.state);
  }
  if (!tracks[physics::kCueBall].on_table)
    return Result<Tracks>::fail("balls before: the cue ball is not on the table");
  return Result<Tracks>::ok(tracks);
}

class LogChecker {
 public:
  explicit LogChecker(const Tracks& tracks) : tracks_(tracks) {}

  // Returns "" or the reason the event contradicts what came before.
  std::string apply(std::size_t index, const Event& event) {
    if (std::string why = checkFrame(index, event); !why.empty()) return why;
    if (std::string why = checkIds(event); !why.empty()) return why;
    if (std::string why = checkAfterRest(event); !why.empty()) return why;
    std::string why = applyMotion(event);
    if (why.empty()) updateRest(event);
    return why;
  }

  const Tracks& tracks() const { return tracks_; }

 private:
  std::string checkFrame(std::size_t index, const Event& event) {
    if (!std::isfinite(event.t) || event.t < 0.0)
      return "event " + std::to_string(index) + ": time is not a finite t >= 0";
    if (index == 0 && (event.type != EventType::Strike || event.ball_a != physics::kCueBall)) {
      return "the log does not start with the strike of the cue ball";
    }
    if (index > 0 && event.type == EventType::Strike) return "a second strike" + at(event);
    if (event.t < last_t_)
      return "event " + std::to_string(index) + at(event) + " is out of time order";
    last_t_ = event.t;
    return "";
  }

  std::string checkIds(const Event& event) const {
    if (!validId(event.ball_a) || !tracks_[event.ball_a].on_table) {
      return "unknown " + ball(event.ball_a) + at(event) + " (not on the table before the shot)";
    }
    if (event.type == EventType::BallBall) {
      if (!validId(event.ball_b) || !tracks_[event.ball_b].on_table) {
        return "unknown " + ball(event.ball_b) + at(event) + " (not on the table before the shot)";
      }
      if (event.ball_a == event.ball_b) return ball(event.ball_a) + " hits itself" + at(event);
    }
    if (event.type == EventType::Pocket && !isPocketName(event.where)) {
      return ball(event.ball_a) + " falls into unknown pocket '" + event.where + "'" + at(event);
    }
    return "";
  }

  std::string checkAfterRest(const Event& event) const {
    if (!all_rest_ || event.type == EventType::SpinToRest || event.type == EventType::Respot)
      return "";
    return ball(event.ball_a) + " has an event" + at(event) +
           " after every ball came to rest at t=" + std::to_string(rest_t_);
  }

  std::string applyMotion(const Event& event) {
    BallTrack& a = tracks_[event.ball_a];
    switch (event.type) {
      case EventType::Strike:
        a.moving = true;
        return "";
      case EventType::BallBall:
        return applyCollision(event);
      case EventType::BallCushion:
        return needsMotion(event, "touches cushion " + event.where);
      case EventType::Airborne:
        return needsMotion(event, "leaves the slate");
      case EventType::Pocket:
      case EventType::OffTable:
        return applyGone(event);
      case EventType::RollToRest:
      case EventType::SpinToRest:
        a.moving = false;
        return "";
      case EventType::Respot:
        a = BallTrack{true, false, false, true, a.gone_by};
        return "";
      case EventType::SlideToRoll:
      case EventType::Land:
        return "";
    }
    return "";
  }

  std::string applyCollision(const Event& event) {
    BallTrack& a = tracks_[event.ball_a];
    BallTrack& b = tracks_[event.ball_b];
    for (int id : {event.ball_a, event.ball_b}) {
      if (tracks_[id].gone) return ball(id) + " hits a ball" + at(event) + " after " + goneText(id);
    }
    if (!a.moving && !b.moving) {
      return ball(event.ball_a) + " and " + ball(event.ball_b) + " collide" + at(event) +
             " while both are at rest";
    }
    a.moving = b.moving = true;
    return "";
  }

  std::string needsMotion(const Event& event, const std::string& what) const {
    const BallTrack& a = tracks_[event.ball_a];
    if (a.gone)
      return ball(event.ball_a) + " " + what + at(event) + " after " + goneText(event.ball_a);
    if (!a.moving)
      return ball(event.ball_a) + " " + what + at(event) + " without being set in motion";
    return "";
  }

  std::string applyGone(const Event& event) {
    const char* what = event.type == EventType::Pocket ? "is pocketed" : "leaves the table";
    if (std::string why = needsMotion(event, what); !why.empty()) return why;
    BallTrack& a = tracks_[event.ball_a];
    a.gone = true;
    a.moving = false;
    a.gone_by = event.type;
    return "";
  }

  std::string goneText(int id) const {
    return tracks_[id].gone_by == EventType::Pocket ? "it was pocketed" : "it left the table";
  }

  void updateRest(const Event& event) {
    for (const BallTrack& t : tracks_) {
      if (t.moving) return;
    }
    if (!all_rest_) rest_t_ = event.t;
    all_rest_ = true;
  }

  Tracks tracks_;
  double last_t_ = 0.0;
  bool all_rest_ = false;
  double rest_t_ = 0.0;
};

// The final state of one ball against what the log said of it.
std::string checkFinal(int id, const BallTrack& track, MotionState state) {
  if (track.respotted) return "";
  bool on = physics::onTable(state);
  if (!track.gone && !on)
    return ball(id) + " ends " + stateName(state) + " but the log never removes it";
  if (track.gone && on) return ball(id) + " leaves play in the log but ends on the table";
  if (track.gone && track.gone_by == EventType::Pocket && state != MotionState::Pocketed) {
    return ball(id) + " is pocketed in the log but ends " + stateName(state);
  }
  return "";
}

std::string checkAfter(const std::vector<physics::Ball>& after, const Tracks& tracks) {
  std::array<bool, kBalls> seen{};
  for (const auto& b : after) {
    if (!validId(b.id)) return "balls after: id " + std::to_string(b.id) + " is not 0-15";
    if (seen[b.id]) return "balls after: " + ball(b.id) + " is listed twice";
    seen[b.id] = true;
    if (!tracks[b.id].on_table) {
      if (physics::onTable(b.state)) return "balls after: " + ball(b.id) + " appears on the table";
      continue;
    }
    if (std::string why = checkFinal(b.id, tracks[b.id], b.state); !why.empty())
      return "balls after: " + why;
  }
  for (int id = 0; id < kBalls; ++id) {
    if (tracks[id].on_table && !seen[id]) return "balls after: " + ball(id) + " is missing";
  }
  return "";
}

}  // namespace

Result<bool> checkShot(const Shot& shot) {
  auto tracks = tracksBefore(shot.before);
  if (!tracks) return Result<bool>::fail(tracks.error());
  if (shot.events.empty()) return Result<bool>::fail("the event log is empty");
  LogChecker checker(*tracks);
  for (std::size_t i = 0; i < shot.events.size(); ++i) {
    if (std::string why = checker.apply(i, shot.events[i]); !why.empty())
      return Result<bool>::fail(why);
  }
  if (std::string why = checkAfter(shot.after, checker.tracks()); !why.empty())
    return Result<bool>::fail(why);
  return Result<bool>::ok(true);
}

}  // namespace pool::rules
