// The spectator's choice of match, its join request and its output.
#include "client/spectate/spectator.h"

#include <algorithm>

#include "client/spectate/json_lines.h"

namespace pool::client {

Spectator::Spectator(GameClient& client, SpectatorConfig config, Emit emit)
    : client_(client), config_(std::move(config)), emit_(std::move(emit)) {
  if (config_.match != "any") target_ = config_.match;
}

void Spectator::step(double now) {
  if (done_) return;
  const auto events = client_.poll();
  const bool had_target = !target_.empty();
  choose(now);
  // A late joiner has the latest state already (transient-local): show it at once.
  if (!had_target && !target_.empty()) {
    if (const MatchView* view = client_.state(target_)) emitState(*view);
  }
  if (target_.empty()) return;
  for (const auto& event : events) handle(event);
  emitFrameCounts();
  // Over: the last shot's result may come a moment after the state; wait for it, briefly.
  if (ending_ && !ending_since_) ending_since_ = now;
  if (ending_ && (last_result_ >= ending_->shot_number || now - *ending_since_ >= kEndLinger)) {
    done_ = true;
  }
}

void Spectator::choose(double now) {
  if (target_.empty()) {
    const auto in_play = client_.lobby().firstInPlay();
    if (!in_play) return;
    target_ = *in_play;
  }
  if (!watching_ && now - sent_at_ >= config_.join_retry) {
    request_ = client_.requestSpectate(target_);
    sent_at_ = now;
  }
}

void Spectator::handle(const ClientEvent& event) {
  if (const auto* answer = std::get_if<JoinAnswer>(&event)) {
    if (!request_ || answer->request != *request_) return;
    watching_ = answer->accepted();
    if (watching_) emit_(spectatingLine(*answer));
  } else if (const auto* view = std::get_if<MatchView>(&event)) {
    if (view->match == target_) emitState(*view);
  } else if (const auto* report = std::get_if<ShotReport>(&event)) {
    if (report->match != target_) return;
    emit_(shotResultLine(*report));
    if (report->final()) last_result_ = std::max(last_result_, report->shot_number);
    // Results from before we joined (kept by the server for late joiners) have no frames here.
    const bool seen_start = joined_at_shot_ && report->shot_number > *joined_at_shot_;
    if (report->final() && seen_start) shots_done_.push_back(report->shot_number);
  } else if (const auto* frame = std::get_if<TableFrame>(&event)) {
    if (frame->match != target_) return;
    countFrame(*frame);
    latest_balls_ = frame->balls;
  } else if (const auto* gone = std::get_if<MatchGone>(&event)) {
    if (gone->match == target_ && config_.exit_when_over) done_ = true;
  }
}

void Spectator::emitState(const MatchView& view) {
  if (printed_revision_ && view.revision <= *printed_revision_) return;
  printed_revision_ = view.revision;
  latest_balls_ = view.balls;
  if (!joined_at_shot_) joined_at_shot_ = view.shot_number;
  emit_(matchStateLine(view));
  if (config_.exit_when_over &&
      (view.phase == MatchPhase::Over || view.phase == MatchPhase::Closed)) {
    ending_ = view;
  }
}

void Spectator::countFrame(const TableFrame& frame) {
  Frames& f = frames_[frame.shot_number];
  f.first = f.count == 0 ? frame.frame : std::min(f.first, frame.frame);
  f.last = f.count == 0 ? frame.frame : std::max(f.last, frame.frame);
  ++f.count;
}

void Spectator::emitFrameCounts() {
  for (std::uint32_t shot : shots_done_) {
    const Frames f = frames_[shot];
    emit_(snapshotsLine(target_, shot, f.count, f.first, f.last));
    frames_.erase(shot);
  }
  shots_done_.clear();
}

}  // namespace pool::client
