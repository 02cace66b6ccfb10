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
Result<Tracks> tracksBefore(const std::vector<physics::Ball>& before, int struck) {
  Tracks tracks{};
  std::array<bool, kBalls> seen{};
  for (const auto& b : before) {
    if (!validId(b.id))
      return Result<Tracks>::fail("balls before: id " + std::to_string(b.id) + " is not 0-21");
    if (seen[b.id]) return Result<Tracks>::fail("balls before: " + ball(b.id) + " is listed twice");
    seen[b.id] = true;
    tracks[b.id].on_table = physics::onTable(b.state);
  }
  if (!tracks[static_cast<std::size_t>(struck)].on_table) {
    return Result<Tracks>::fail(struck == physics::kCueBall
                                    ? "balls before: the cue ball is not on the table"
                                    : "balls before: the struck " + ball(struck) +
                                          " is not on the table");
  }
  return Result<Tracks>::ok(tracks);
}

class LogChecker {
 public:
  LogChecker(const Tracks& tracks, int struck) : tracks_(tracks), struck_(struck) {}

  // Refuses an event that contradicts what came before, with the reason.
  Check<> apply(std::size_t index, const Event& event) {
    if (auto ok = checkFrame(index, event); !ok) return ok;
    if (auto ok = checkIds(event); !ok) return ok;
    if (auto ok = checkAfterRest(event); !ok) return ok;
    auto ok = applyMotion(event);
    if (ok) updateRest(event);
    return ok;
  }

  const Tracks& tracks() const { return tracks_; }

 private:
  Check<> checkFrame(std::size_t index, const Event& event) {
    if (!std::isfinite(event.t) || event.t < 0.0)
      return Check<>::refuse("bad_event_order",
                             "event " + std::to_string(index) + ": time is not a finite t >= 0");
    if (index == 0 && (event.type != EventType::Strike || event.ball_a != struck_)) {
      return Check<>::refuse("bad_event_order",
                             struck_ == physics::kCueBall
                                 ? "the log does not start with the strike of the cue ball"
                                 : "the log does not start with the strike of " + ball(struck_));
    }
    if (index > 0 && event.type == EventType::Strike)
      return Check<>::refuse("bad_event_order", "a second strike" + at(event));
    if (event.t < last_t_)
      return Check<>::refuse("bad_event_order", "event " + std::to_string(index) + at(event) +
                                                    " is out of time order");
    last_t_ = event.t;
    return Check<>::pass();
  }

  Check<> checkIds(const Event& event) const {
    if (!validId(event.ball_a) || !tracks_[event.ball_a].on_table) {
      return Check<>::refuse("unknown_ball", "unknown " + ball(event.ball_a) + at(event) +
                                                 " (not on the table before the shot)");
    }
    if (event.type == EventType::BallBall) {
      if (!validId(event.ball_b) || !tracks_[event.ball_b].on_table) {
        return Check<>::refuse("unknown_ball", "unknown " + ball(event.ball_b) + at(event) +
                                                   " (not on the table before the shot)");
      }
      if (event.ball_a == event.ball_b)
        return Check<>::refuse("unknown_ball", ball(event.ball_a) + " hits itself" + at(event));
    }
    if (event.type == EventType::Pocket && !isPocketName(event.where)) {
      return Check<>::refuse("unknown_ball", ball(event.ball_a) + " falls into unknown pocket '" +
                                                 event.where + "'" + at(event));
    }
    return Check<>::pass();
  }

  Check<> checkAfterRest(const Event& event) const {
    if (!all_rest_ || event.type == EventType::SpinToRest || event.type == EventType::Respot)
      return Check<>::pass();
    return Check<>::refuse("event_after_rest",
                           ball(event.ball_a) + " has an event" + at(event) +
                               " after every ball came to rest at t=" + std::to_string(rest_t_));
  }

  Check<> applyMotion(const Event& event) {
    BallTrack& a = tracks_[event.ball_a];
    switch (event.type) {
      case EventType::Strike:
        a.moving = true;
        return Check<>::pass();
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
        return Check<>::pass();
      case EventType::Respot:
        a = BallTrack{true, false, false, true, a.gone_by};
        return Check<>::pass();
      case EventType::SlideToRoll:
      case EventType::Land:
        return Check<>::pass();
    }
    return Check<>::pass();
  }

  Check<> applyCollision(const Event& event) {
    BallTrack& a = tracks_[event.ball_a];
    BallTrack& b = tracks_[event.ball_b];
    for (int id : {event.ball_a, event.ball_b}) {
      if (tracks_[id].gone)
        return Check<>::refuse("bad_collision",
                               ball(id) + " hits a ball" + at(event) + " after " + goneText(id));
    }
    if (!a.moving && !b.moving) {
      return Check<>::refuse("bad_collision", ball(event.ball_a) + " and " + ball(event.ball_b) +
                                                  " collide" + at(event) +
                                                  " while both are at rest");
    }
    a.moving = b.moving = true;
    return Check<>::pass();
  }

  Check<> needsMotion(const Event& event, const std::string& what) const {
    const BallTrack& a = tracks_[event.ball_a];
    if (a.gone)
      return Check<>::refuse("no_motion", ball(event.ball_a) + " " + what + at(event) + " after " +
                                              goneText(event.ball_a));
    if (!a.moving)
      return Check<>::refuse("no_motion", ball(event.ball_a) + " " + what + at(event) +
                                              " without being set in motion");
    return Check<>::pass();
  }

  Check<> applyGone(const Event& event) {
    const char* what = event.type == EventType::Pocket ? "is pocketed" : "leaves the table";
    if (auto ok = needsMotion(event, what); !ok) return ok;
    BallTrack& a = tracks_[event.ball_a];
    a.gone = true;
    a.moving = false;
    a.gone_by = event.type;
    return Check<>::pass();
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
  int struck_ = physics::kCueBall;
  double last_t_ = 0.0;
  bool all_rest_ = false;
  double rest_t_ = 0.0;
};

// The final state of one ball against what the log said of it.
Check<> checkFinal(int id, const BallTrack& track, MotionState state) {
  if (track.respotted) return Check<>::pass();
  bool on = physics::onTable(state);
  if (!track.gone && !on)
    return Check<>::refuse("bad_final_state", ball(id) + " ends " + stateName(state) +
                                                  " but the log never removes it");
  if (track.gone && on)
    return Check<>::refuse("bad_final_state",
                           ball(id) + " leaves play in the log but ends on the table");
  if (track.gone && track.gone_by == EventType::Pocket && state != MotionState::Pocketed) {
    return Check<>::refuse("bad_final_state",
                           ball(id) + " is pocketed in the log but ends " + stateName(state));
  }
  return Check<>::pass();
}

Check<> checkAfter(const std::vector<physics::Ball>& after, const Tracks& tracks) {
  std::array<bool, kBalls> seen{};
  for (const auto& b : after) {
    if (!validId(b.id))
      return Check<>::refuse("bad_balls_after",
                             "balls after: id " + std::to_string(b.id) + " is not 0-21");
    if (seen[b.id])
      return Check<>::refuse("bad_balls_after", "balls after: " + ball(b.id) + " is listed twice");
    seen[b.id] = true;
    if (!tracks[b.id].on_table) {
      if (physics::onTable(b.state))
        return Check<>::refuse("bad_balls_after",
                               "balls after: " + ball(b.id) + " appears on the table");
      continue;
    }
    if (auto ok = checkFinal(b.id, tracks[b.id], b.state); !ok)
      return Check<>::refuse(ok.code(), "balls after: " + ok.error());
  }
  for (int id = 0; id < kBalls; ++id) {
    if (tracks[id].on_table && !seen[id])
      return Check<>::refuse("bad_balls_after", "balls after: " + ball(id) + " is missing");
  }
  return Check<>::pass();
}

}  // namespace

Check<> checkShot(const Shot& shot, int struck) {
  if (!validId(struck))
    return Check<>::refuse("bad_balls_before",
                           "the struck ball " + std::to_string(struck) + " is not 0-21");
  auto tracks = tracksBefore(shot.before, struck);
  if (!tracks) return Check<>::refuse("bad_balls_before", tracks.error());
  if (shot.events.empty()) return Check<>::refuse("empty_log", "the event log is empty");
  LogChecker checker(*tracks, struck);
  for (std::size_t i = 0; i < shot.events.size(); ++i) {
    if (auto ok = checker.apply(i, shot.events[i]); !ok) return ok;
  }
  if (auto ok = checkAfter(shot.after, checker.tracks()); !ok) return ok;
  return Check<>::pass();
}

}  // namespace pool::rules
