// Asking for a stored shot, keeping the answer and playing its rebuilt frames on the caller's
// clock.
#include "client/app/stored_replay.h"

#include <algorithm>

#include "client/app/shot_story.h"

namespace pool::app {

const ReplayFrame* frameAt(const std::vector<ReplayFrame>& frames, double t) {
  if (frames.empty()) return nullptr;
  // The first frame after `t`; the one before it is shown.
  const auto after = std::upper_bound(frames.begin(), frames.end(), t,
                                      [](double at, const ReplayFrame& f) { return at < f.t; });
  return after == frames.begin() ? &frames.front() : &*std::prev(after);
}

std::uint32_t steppedShot(std::uint32_t shot, int step, std::uint32_t shots) {
  const std::int64_t moved = static_cast<std::int64_t>(shot) + step;
  return static_cast<std::uint32_t>(
      std::clamp<std::int64_t>(moved, 1, std::max<std::int64_t>(shots, 1)));
}

std::string storedShotTitle(const protocol::HistoryShot& shot) {
  SeatNames names{"Player 1", "Player 2"};
  for (std::size_t s = 0; s < 2; ++s) {
    if (!shot.players[s].empty()) names[s] = shot.players[s];
  }
  const std::string shooter = names[shot.seat == 1 ? 1 : 0];
  std::string title = "Replay of " + shot.match + ", shot " + std::to_string(shot.shot_number) +
                      " of " + std::to_string(shot.shots) + ": " + shooter;
  const std::string verdict = verdictInWords(shot.verdict_text, names);
  if (!verdict.empty()) title += " - " + verdict;
  return title;
}

void StoredReplay::open(std::string match, std::uint32_t shot, std::uint32_t known_shots) {
  close();
  match_ = std::move(match);
  last_wanted_ = shot == 0;
  shots_ = 0;
  ask(shot != 0 ? shot : std::max<std::uint32_t>(known_shots, 1));
}

void StoredReplay::close() {
  match_.clear();
  wanted_ = 0;
  shots_ = 0;
  last_wanted_ = false;
  requests_.clear();
  asked_at_.reset();
  asks_ = 0;
  due_ = false;
  shown_.reset();
  frames_.clear();
  problem_.clear();
}

void StoredReplay::ask(std::uint32_t shot) {
  wanted_ = shot;
  requests_.clear();
  asked_at_.reset();
  asks_ = 0;
  due_ = true;
}

std::optional<std::uint32_t> StoredReplay::due(double now) {
  if (!isOpen() || !waiting()) return std::nullopt;
  if (!due_ && asked_at_ && now - *asked_at_ >= kAskAgain) {
    if (asks_ >= kAsksPerShot) {
      if (problem_.empty()) {
        problem_ =
            "no answer from the server of " + match_ + " for shot " + std::to_string(wanted_);
      }
      asked_at_.reset();
      return std::nullopt;
    }
    due_ = true;
  }
  if (!due_) return std::nullopt;
  return wanted_;
}

void StoredReplay::asked(std::uint32_t request, double now) {
  requests_.insert(request);
  asked_at_ = now;
  ++asks_;
  due_ = false;
}

void StoredReplay::notAsked(const std::string& why, double now) {
  problem_ = why;
  asked_at_ = now;
  ++asks_;
  due_ = false;
}

bool StoredReplay::take(protocol::HistoryShot answer, double now) {
  if (!isOpen() || !requests_.count(answer.request) || answer.match != match_) return false;
  // A repeated ask's second answer, or one for a shot no longer wanted, changes nothing.
  if (!waiting() || (answer.found && answer.shot_number != wanted_)) return false;
  shots_ = answer.shots;
  if (!answer.found) {
    // The last shot wanted: the answer tells how many there are; the very last may still be
    // being played: then the one before it is the last to show.
    if (last_wanted_ && shots_ > 0 && wanted_ != shots_) {
      ask(shots_);
      return true;
    }
    if (last_wanted_ && wanted_ == shots_ && wanted_ > 1) {
      last_wanted_ = false;
      ask(wanted_ - 1);
      return true;
    }
    problem_ = answer.error;
    requests_.clear();
    asked_at_.reset();
    due_ = false;
    return true;
  }
  if (last_wanted_ && answer.shot_number < answer.shots) {
    ask(answer.shots);  // the match has gone on: its last one
    return true;
  }
  last_wanted_ = false;
  problem_.clear();
  requests_.clear();
  asked_at_.reset();
  frames_ = replayFrames(answer.before, answer.events, answer.after, kHz);
  shown_ = std::move(answer);
  again(now);
  return true;
}

bool StoredReplay::previous() {
  if (!isOpen() || !hasPrevious()) return false;
  last_wanted_ = false;
  ask(steppedShot(wanted_, -1, shots_));
  problem_.clear();
  return true;
}

bool StoredReplay::next() {
  if (!isOpen() || !hasNext()) return false;
  last_wanted_ = false;
  ask(steppedShot(wanted_, 1, shots_));
  problem_.clear();
  return true;
}

void StoredReplay::again(double now) {
  start_ = now + kLead;
}

std::optional<std::vector<physics::Ball>> StoredReplay::balls(double now) const {
  if (!shown_) return std::nullopt;
  if (const ReplayFrame* f = frameAt(frames_, time(now))) return f->balls;
  return shown_->after;
}

bool StoredReplay::atRest(double now) const {
  return shown_ && (frames_.empty() || time(now) >= frames_.back().t);
}

}  // namespace pool::app
