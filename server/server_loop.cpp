// One pass of the server: requests in, answers, frames and state out.
#include "server/server_loop.h"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "core/text.h"
#include "server/match_publish.h"

namespace pool::server {

ServerLoop::ServerLoop(const ServerConfig& config, MatchRegistry& registry,
                       net::ServerTransport& transport, store::MatchStore* store)
    : config_(config),
      registry_(registry),
      transport_(transport),
      limits_(commandLimits(registry.table().spec)),
      store_(store),
      epoch_(std::chrono::steady_clock::now()) {}

double ServerLoop::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count();
}

void ServerLoop::run(const std::atomic<bool>& stop) {
  storeChanges({});
  publishChanges();
  while (!stop.load()) {
    transport_.wait(waitTimeout(now()));
    step(now());
  }
}

void ServerLoop::step(double now) {
  // The loop wakes every kMaxWait at most: a much longer gap means the process was stopped or
  // suspended (SIGSTOP, a closed laptop lid, a stalled VM). That time counts against nobody.
  if (last_step_ && now - *last_step_ > kStall) {
    const double stalled = now - *last_step_ - kMaxWait.count() / 1000.0;
    spdlog::warn("the server was not running for {:.1f} s: grace periods and frames resume",
                 stalled);
    registry_.pause(stalled);
  }
  last_step_ = now;
  readJoins(now);
  readCommands(now);
  stepReplay(now);
  publishFrames(now);
  registry_.expireAway(now, config_.grace);
  for (const auto& [match, answer] : registry_.tickClocks(now)) {
    if (!answer.accepted()) {
      spdlog::error("shot clock of {}: {}", match, answer.rejection.text);
      continue;
    }
    spdlog::info("shot clock of {}: seat {} ran out of time", match, answer.seat);
    storeShot(answer, match);
    publishResult(match, answer);
  }
  const auto closed = registry_.sweepEmpty();
  for (const auto& id : closed) dispose(id);
  // A table is always free for the next players (two asking at once meet there).
  if (const int opened = registry_.keepFreeTables(config_.tables); opened > 0) {
    spdlog::info("opened {} free table{}", opened, opened == 1 ? "" : "s");
  }
  storeChanges(closed);
  publishChanges();
}

std::chrono::nanoseconds ServerLoop::waitTimeout(double now) const {
  const auto due = registry_.nextFrameDue();
  if (!due) return kMaxWait;
  const auto until = std::chrono::duration<double>(std::max(0.0, *due - now));
  return std::min<std::chrono::nanoseconds>(
      kMaxWait, std::chrono::duration_cast<std::chrono::nanoseconds>(until));
}

void ServerLoop::warnIfFailed(const std::string& error, const char* what) const {
  if (!error.empty()) spdlog::warn("{}: {}", what, error);
}

void ServerLoop::readJoins(double now) {
  for (auto& event : transport_.takeJoins()) {
    if (const auto* gone = std::get_if<net::ClientGone>(&event)) {
      spdlog::info("client {} is gone ({})", escapedForLog(gone->client), gone->why);
      registry_.clientGone(gone->client, now);
      transport_.forgetClient(gone->client);  // its last reply need not be kept any more
    } else if (const auto* bad = std::get_if<net::UnreadableJoin>(&event)) {
      spdlog::warn("unreadable join request from {}: {}", escapedForLog(bad->client), bad->reason);
      // The action itself may be what could not be read, so the reply does not echo it.
      JoinCommand echo;
      echo.client = bad->client;
      echo.request = bad->request;
      echo.match = bad->match;
      warnIfFailed(
          transport_.publish(replyTo(echo, JoinAnswer::refuse(JoinOutcome::NotAllowed, bad->reason),
                                     registry_.serverId())),
          "join reply");
    } else {
      answerJoin(std::get<JoinCommand>(event));
    }
  }
}

void ServerLoop::answerJoin(const JoinCommand& command) {
  const JoinAnswer answer = registry_.join(command);
  spdlog::info("join {} {} by {} ({}): {} {}", toString(command.action),
               escapedForLog(command.match), escapedForLog(command.client),
               escapedForLog(command.name), toString(answer.outcome), escapedForLog(answer.reason));
  // A seat (and its token) is stored before the player hears of it: a crash right after the
  // reply cannot take the seat away again.
  storeChanges({});
  warnIfFailed(transport_.publish(replyTo(command, answer, registry_.serverId())), "join reply");
}

void ServerLoop::readCommands(double now) {
  for (auto& in : transport_.takeCommands(limits_)) {
    if (!in.request) {
      CommandAnswer refusal;
      refusal.seat = in.seat;
      refusal.seq = in.seq;
      refusal.rejection = {in.bad_signature ? Reject::BadSignature : Reject::Malformed, in.problem};
      refused(in.match, refusal, now);  // logged escaped
      continue;
    }
    const CommandAnswer answer = registry_.shoot(*in.request, now);
    if (!answer.accepted()) {
      refused(in.match, answer, now);
      continue;
    }
    storeShot(answer, in.match);
    spdlog::info("command {} seat {} seq {}: accepted, shot {}", in.match, answer.seat, answer.seq,
                 answer.shot_number);
    publishResult(in.match, answer);
  }
  if (auto summary = rejections_.summary(now)) spdlog::info("{}", *summary);
}

void ServerLoop::refused(const std::string& match, const CommandAnswer& answer, double now) {
  spdlog::debug("command {} seat {} seq {}: {} ({})", escapedForLog(match), answer.seat, answer.seq,
                toString(answer.rejection.reason), escapedForLog(answer.rejection.text));
  rejections_.add(answer.rejection.reason, now);
  publishResult(match, answer);
}

void ServerLoop::publishResult(const std::string& match, const CommandAnswer& answer) {
  const auto result = answer.done ? finalReport(match, *answer.done) : commandReport(match, answer);
  // A result keyed by a match or seat that does not exist is not kept for late readers: the
  // writer would otherwise hold one instance per made-up key for good.
  const bool keep = registry_.find(match) && (answer.seat == 0 || answer.seat == 1);
  warnIfFailed(transport_.publish(result, keep), "shot result");
}

void ServerLoop::stepReplay(double now) {
  if (!replay_ || replay_reported_) return;
  // A replay is for spectators: it starts once someone reads its results, so that nobody who
  // was there from the start misses its first shots to discovery.
  if (!replay_started_) {
    if (transport_.resultReaders() == 0) return;
    replay_started_ = true;
    spdlog::info("replay {}: a spectator is here, starting", replay_->matchId());
  }
  if (auto answer = replay_->step(now)) {
    spdlog::info("replay {}: seat {} seq {} {}", replay_->matchId(), answer->seat, answer->seq,
                 answer->accepted() ? "replayed" : answer->rejection.text);
    publishResult(replay_->matchId(), *answer);
  }
  if (!replay_->done()) return;
  replay_reported_ = true;
  for (const auto& difference : replay_->differences()) {
    spdlog::error("replay {}: {}", replay_->matchId(), difference);
  }
  spdlog::info("replay {} done: {} commands replayed, {} differ from the stored shots",
               replay_->matchId(), replay_->replayed(), replay_->differences().size());
}

void ServerLoop::storeShot(const CommandAnswer& answer, const std::string& match) {
  const Match* m = registry_.find(match);
  if (!store_ || !answer.record || !m) return;
  const auto start = std::chrono::steady_clock::now();
  store_->recordShot(*answer.record, rules::describe(answer.record->verdict),
                     registry_.snapshotOf(*m));
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  spdlog::info("stored shot {} of {} (seat {} seq {}) in {:.2f} ms", answer.record->shot_number,
               match, answer.seat, answer.seq, ms);
}

void ServerLoop::storeChanges(const std::vector<std::string>& closed) {
  if (!store_) return;
  std::vector<MatchSnapshot> changed;
  for (Match* m : registry_.matches()) {
    auto& stored = stored_[m->id()];
    if (stored == m->revision()) continue;
    stored = m->revision();
    changed.push_back(registry_.snapshotOf(*m));
  }
  for (const auto& id : closed) {
    stored_.erase(id);
    store_->closeMatch(id);
  }
  if (!changed.empty()) store_->saveMatches(registry_.serverId(), registry_.opened(), changed);
}

void ServerLoop::publishFrames(double now) {
  for (Match* m : registry_.matches()) {
    if (!m->inMotion()) continue;
    const DueFrames due = m->takeDueFrames(now);
    for (std::size_t i = 0; i < due.frames.size(); ++i) {
      const auto frame = static_cast<std::uint32_t>(due.first + i);
      warnIfFailed(transport_.publish(frameOf(m->id(), frame, due.shot_number, due.frames[i])),
                   "snapshot");
    }
    if (auto report = m->finishShot()) {
      spdlog::info("shot {} of {} done: {}", report->shot_number, m->id(), m->lastVerdict());
      warnIfFailed(transport_.publish(finalReport(m->id(), *report)), "shot result");
    }
  }
}

void ServerLoop::publishChanges() {
  for (Match* m : registry_.matches()) {
    auto& published = published_[m->id()];
    if (published == m->revision()) continue;
    published = m->revision();
    warnIfFailed(transport_.publish(lobbyEntryOf(*m, registry_.serverId())), "match info");
    warnIfFailed(transport_.publish(matchViewOf(*m, last_step_)), "match state");
  }
}

void ServerLoop::dispose(const std::string& match) {
  spdlog::info("match {} closed", match);
  transport_.dispose(match);
  published_.erase(match);
}

void ServerLoop::disposeAll() {
  for (Match* m : registry_.matches()) dispose(m->id());
}

}  // namespace pool::server
