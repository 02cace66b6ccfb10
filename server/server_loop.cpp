// One pass of the server: requests in, answers, frames and state out.
#include "server_loop.h"

#include <spdlog/spdlog.h>

#include <algorithm>

#include "net/wire_fields.h"
#include "wire_messages.h"
#include "wire_requests.h"

namespace pool::server {

namespace {

template <class T>
void publish(const net::Writer<T>& writer, const T& sample, const char* what) {
  if (auto status = writer.write(sample); !status) spdlog::warn("{}: {}", what, status.error);
}

}  // namespace

ServerLoop::ServerLoop(const ServerConfig& config, MatchRegistry& registry, ServerBus& bus,
                       store::MatchStore* store)
    : config_(config),
      registry_(registry),
      bus_(bus),
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
    bus_.waitset.wait(waitTimeout(now()));
    step(now());
  }
}

void ServerLoop::step(double now) {
  readJoins(now);
  readCommands(now);
  stepReplay(now);
  publishFrames(now);
  registry_.expireAway(now, config_.grace);
  const auto closed = registry_.sweepEmpty();
  for (const auto& id : closed) dispose(id);
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

void ServerLoop::readJoins(double now) {
  for (auto& sample : bus_.join_requests.takeWithNotices()) {
    const pool_JoinRequest& r = *sample;
    if (!sample.meta().valid) {
      // The client's JoinRequest writer is gone (lease expired or deleted): it vanished.
      if (sample.meta().instance != net::InstanceState::Alive) {
        const std::string client(net::textOf(r.client));
        spdlog::info("client {} is gone ({})", client, net::toString(sample.meta().instance));
        registry_.clientGone(client, now);
        pool_JoinReply key{};
        net::setText(key.client, client);
        bus_.join_replies.unregister(key);  // its last reply need not be kept any more
      }
      continue;
    }
    auto command = joinCommand(r);
    if (!command) {
      spdlog::warn("unreadable join request: {}", command.error());
      publish(bus_.join_replies, unreadableJoinReply(r, command.error(), registry_.serverId()),
              "join reply");
      continue;
    }
    const JoinAnswer answer = registry_.join(*command);
    spdlog::info("join {} {} by {} ({}): {} {}", toString(command->action), command->match,
                 command->client, command->name, toString(answer.outcome), answer.reason);
    // A seat (and its token) is stored before the player hears of it: a crash right after the
    // reply cannot take the seat away again.
    storeChanges({});
    publish(bus_.join_replies, joinReply(*command, answer, registry_.serverId()), "join reply");
  }
}

void ServerLoop::readCommands(double now) {
  for (auto& sample : bus_.commands.take()) {
    ReadCommand read = readCommand(*sample, limits_);
    const std::string match(net::textOf(sample->match));
    if (!read.refusal.accepted()) {
      refused(match, read.refusal, now);
      continue;
    }
    const CommandAnswer answer = registry_.shoot(read.request, now);
    if (!answer.accepted()) {
      refused(match, answer, now);
      continue;
    }
    storeShot(answer, match);
    spdlog::info("command {} seat {} seq {}: accepted, shot {}", match, answer.seat, answer.seq,
                 answer.shot_number);
    publishResult(match, answer);
  }
  if (auto summary = rejections_.summary(now)) spdlog::info("{}", *summary);
}

void ServerLoop::refused(const std::string& match, const CommandAnswer& answer, double now) {
  spdlog::debug("command {} seat {} seq {}: {} ({})", match, answer.seat, answer.seq,
                toString(answer.rejection.reason), answer.rejection.text);
  rejections_.add(answer.rejection.reason, now);
  publishResult(match, answer);
}

void ServerLoop::publishResult(const std::string& match, const CommandAnswer& answer) {
  const auto result = answer.done ? finalResult(match, *answer.done) : commandResult(match, answer);
  publish(bus_.results, *result, "shot result");
  // A result keyed by a match or seat that does not exist is not kept for late readers: the
  // writer would otherwise hold one instance per made-up key for good.
  if (!registry_.find(match) || (answer.seat != 0 && answer.seat != 1)) {
    bus_.results.unregister(*result);
  }
}

void ServerLoop::stepReplay(double now) {
  if (!replay_ || replay_reported_) return;
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
      publish(bus_.snapshots, *snapshot(m->id(), frame, due.shot_number, due.frames[i]),
              "snapshot");
    }
    if (auto report = m->finishShot()) {
      spdlog::info("shot {} of {} done: {}", report->shot_number, m->id(), m->lastVerdict());
      publish(bus_.results, *finalResult(m->id(), *report), "shot result");
    }
  }
}

void ServerLoop::publishChanges() {
  for (Match* m : registry_.matches()) {
    auto& published = published_[m->id()];
    if (published == m->revision()) continue;
    published = m->revision();
    publish(bus_.match_info, matchInfo(*m, registry_.serverId()), "match info");
    publish(bus_.states, *matchState(*m), "match state");
  }
}

void ServerLoop::dispose(const std::string& match) {
  spdlog::info("match {} closed", match);
  pool_MatchInfo info{};
  net::setText(info.match, match);
  bus_.match_info.dispose(info);
  net::Sample<pool_MatchState> state;
  net::setText(state->match, match);
  bus_.states.dispose(*state);
  for (const std::int16_t seat : {std::int16_t{0}, std::int16_t{1}}) {
    net::Sample<pool_ShotResult> result;
    net::setText(result->match, match);
    result->seat = seat;
    bus_.results.dispose(*result);
  }
  published_.erase(match);
}

void ServerLoop::disposeAll() {
  for (Match* m : registry_.matches()) dispose(m->id());
}

}  // namespace pool::server
