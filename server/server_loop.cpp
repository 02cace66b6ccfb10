// One pass of the server: requests in, answers, frames and state out.
#include "server/server_loop.h"

#include <spdlog/spdlog.h>

#include <algorithm>
#include <cmath>

#include "core/text.h"
#include "server/match_publish.h"
#include "server/store/rating_book.h"

namespace pool::server {

ServerLoop::ServerLoop(const ServerConfig& config, MatchRegistry& registry,
                       net::ServerTransport& transport, store::MatchStore* store)
    : config_(config),
      registry_(registry),
      transport_(transport),
      limits_(serverLimits(registry.table().spec)),
      store_(store),
      players_(transport, registry.serverId()),
      tournaments_(registry, store),
      epoch_(std::chrono::steady_clock::now()) {
  if (store_) {
    history_.emplace(*store_, registry.serverId());
    history_->inMotion([this](const std::string& match, std::uint32_t shot) {
      const Match* m = registry_.find(match);
      return m && m->inMotion() && m->shotInMotion() == shot;
    });
  }
  tournaments_.restore();
}

double ServerLoop::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count();
}

void ServerLoop::run(const std::atomic<bool>& stop) {
  storeChanges({});
  publishChanges(now());
  if (store_) {
    for (const auto& error : players_.publishRecent(*store_, kPlayersAtStart))
      warnIfFailed(error, "player stats");
  }
  while (!stop.load()) {
    transport_.wait(waitTimeout(now()));
    step(now());
    if (guard_) fault_ = guard_(now());
    if (!fault_.empty()) break;
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
  // The database going away is noticed at the next write, and at least once a second.
  if (store_ && now - file_checked_ >= 1.0) {
    file_checked_ = now;
    store_->checkStillThere();
  }
  readJoins(now);
  relayAims(now);  // first: a stroke's aim still finds its turn open when its command comes along
  readCommands(now);
  answerHistory(now);
  stepReplay(now);
  publishFrames(now);
  stepTournaments(now);  // before the sweep: a decided match is read before it may go
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
  for (const auto& id : closed) {
    publishClosing(id);
    dispose(id);
  }
  // A table is always free for the next players (two asking at once meet there).
  if (const int opened = registry_.keepFreeTables(config_.tables); opened > 0) {
    spdlog::info("opened {} free table{}", opened, opened == 1 ? "" : "s");
  }
  storeChanges(closed);
  publishChanges(now);
  serveAdmin(now);
}

void ServerLoop::serveAdmin(double now) {
  if (!admin_ || !desk_) return;
  const auto lines = admin_->poll();
  if (lines.empty()) return;
  for (const auto& in : lines) {
    ++counters_.admin_requests;
    const AdminDesk::Reply reply = desk_->answer(in.line);
    if (!reply.ok) {
      ++counters_.admin_refused;
      spdlog::warn("admin request refused: {}", escapedForLog(reply.line));
    }
    admin_->reply(in.connection, reply.line);
  }
  // A closed match is stored and its players read its last state before the next pass drops it.
  storeChanges({});
  publishChanges(now);
}

template <class Write>
double ServerLoop::timedCommit(Write&& write) {
  const auto start = std::chrono::steady_clock::now();
  write();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  counters_.commit(ms);
  return ms;
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
    if (const auto* bad = std::get_if<net::UnreadableJoin>(&event)) {
      // The action itself may be what could not be read, so the reply does not echo it.
      JoinCommand echo;
      echo.client = bad->client;
      echo.request = bad->request;
      echo.match = bad->match;
      if (!withinSenderLimit(bad->sender, bad->writer, echo, now)) continue;
      spdlog::debug("unreadable join request from {}: {}", escapedForLog(bad->client), bad->reason);
      joins_.add("unreadable", now);
      ++counters_.joins_refused;
      reply(echo, JoinAnswer::refuse(JoinOutcome::NotAllowed, bad->reason), bad->sender,
            bad->writer, false, now);
    } else {
      const auto& join = std::get<net::IncomingJoin>(event);
      answerJoin(join.request, join.sender, join.writer, now);
    }
  }
  sweepPresence(now);
  if (joins_.due(now)) {
    // What a summary counts is what is still held: the client buckets full again go first.
    rate_.sweep(now);
  }
  if (auto summary = joins_.summary(now, registry_.spectators(), trackedClients())) {
    spdlog::info("{}", *summary);
  }
  // Joins, refused commands and dropped aims alike: a flood of any of them frees what it used
  // once it is over (DDS samples and instances, answers), which glibc keeps until trimmed.
  if (heap_trim_.due(joins_.total() + counters_.commands_refused + aims_.droppedInAll(), now)) {
    // After kQuiet seconds without joins every flooding client's bucket is full again: swept
    // here, what is still tracked is what the flood left behind.
    rate_.sweep(now);
    const long released = releaseFreeHeap();
    spdlog::info(
        "a flood is over: {:.1f} MB of freed memory given back, {:.1f} MB of heap in use, {} "
        "clients tracked",
        static_cast<double>(released) / (1024.0 * 1024.0),
        static_cast<double>(heapInUse()) / (1024.0 * 1024.0), trackedClients());
  }
}

void ServerLoop::reply(const JoinCommand& to, const JoinAnswer& answer, const std::string& sender,
                       std::uint64_t writer, bool seated, double now) {
  warnIfFailed(transport_.publish(replyTo(to, answer, registry_.serverId())), "join reply");
  // The reply is kept (an instance per client) until the client is gone: its presence is tracked
  // from now on, whoever it is.
  for (const auto& gone : presence_.answered(to.client, writer, sender, seated)) {
    letGo(gone, now, "one writer's clients past their bound");
  }
}

void ServerLoop::sweepPresence(double now) {
  if (now - untied_at_ >= 1.0) {
    untied_at_ = now;
    // A client's presence stays its seat request's writer's while a seat names it (away too: a
    // player back from a stall rejoins under it); seats freed or left let it go.
    presence_.untieUnless([this](const std::string& client) { return registry_.seats(client); });
    // The join buckets of clients that asked once (a flood of invented ids) go once full again,
    // whether or not anyone asks after them.
    rate_.sweep(now);
    sender_rate_.sweep(now);
    stray_answers_.sweep(now);
  }
  const std::uint64_t epoch = transport_.joinWriterEpoch();
  if (epoch == join_writer_epoch_ && !presence_.fresh()) return;
  join_writer_epoch_ = epoch;
  for (const auto& gone : presence_.sweep(transport_.joinWriters())) {
    letGo(gone, now, "its writer is gone");
  }
}

void ServerLoop::letGo(const Presence::Gone& gone, double now, const char* why) {
  // A seated player's going matters to an operator; a spectator's is counted.
  if (registry_.clientGone(gone.client, now)) {
    spdlog::info("client {} is gone ({})", escapedForLog(gone.client), why);
  } else {
    spdlog::debug("client {} is gone ({})", escapedForLog(gone.client), why);
    joins_.add("gone", now);
  }
  transport_.forgetClient(gone.client);  // its last reply need not be kept any more
  rate_.forget(senderClient(gone.sender, gone.client));
}

std::string ServerLoop::senderClient(const std::string& sender, const std::string& client) {
  return sender + " " + client;
}

std::size_t ServerLoop::trackedClients() const {
  return transport_.keptReplies() + rate_.tracked();
}

bool ServerLoop::withinSenderLimit(const std::string& sender, std::uint64_t writer,
                                   const JoinCommand& echo, double now) {
  if (sender_rate_.allow(sender, now)) return true;
  joins_.add("over the per-participant limit", now);
  ++counters_.joins_refused;
  if (sender_rate_.tellRefusal(sender, now)) {
    const auto refusal = JoinAnswer::refuse(
        JoinOutcome::NotAllowed,
        "too many join requests: at most " +
            std::to_string(static_cast<int>(2 * JoinRateLimit::kPerSecond)) +
            " a second from one DDS participant, whatever client ids they carry");
    reply(echo, refusal, sender, writer, false, now);
  }
  return false;
}

void ServerLoop::answerJoin(const JoinCommand& command, const std::string& sender,
                            std::uint64_t writer, double now) {
  // A client over its own limit is refused (one instance answered again and again); a request
  // within it must still be within its participant's (many client ids from one participant).
  // The bucket is the sending participant's for that client id: someone else flooding under the
  // same id empties a bucket of their own, and the client's own requests reach their checks.
  const std::string bucket = senderClient(sender, command.client);
  if (!rate_.allow(bucket, now)) {
    joins_.add("over the per-client limit", now);
    ++counters_.joins_refused;
    const auto refusal = JoinAnswer::refuse(
        JoinOutcome::NotAllowed, "too many join requests: at most " +
                                     std::to_string(static_cast<int>(JoinRateLimit::kPerSecond)) +
                                     " a second per client from one DDS participant");
    reply(command, refusal, sender, writer, false, now);
    return;
  }
  if (!withinSenderLimit(sender, writer, command, now)) return;
  // An entry names a tournament in the match field; everything else goes to the matches.
  const JoinAnswer answer = command.action == JoinAction::Enter
                                ? tournaments_.enter(command, sender)
                                : registry_.join(command);
  ++(answer.accepted() ? counters_.joins_accepted : counters_.joins_refused);
  const auto line = [&] {
    return fmt::format("join {} {} by {} ({}): {} {}", toString(command.action),
                       escapedForLog(command.match), escapedForLog(command.client),
                       escapedForLog(command.name), toString(answer.outcome),
                       escapedForLog(answer.reason));
  };
  if (answer.accepted() && protocol::changesSeat(command)) {
    spdlog::info("{}", line());
  } else {
    // Spectators and refusals cost one summary line a second, however many there are.
    spdlog::debug("{}", line());
    joins_.add(std::string(toString(command.action)) + " " + toString(answer.outcome), now);
  }
  // A seat (and its token) is stored before the player hears of it: a crash right after the
  // reply cannot take the seat away again. Spectators change nothing stored.
  storeChanges({});
  // An accepted seat request (signed by the seat's key) ties the client's presence to its writer.
  const bool seated =
      answer.accepted() && protocol::changesSeat(command) && command.action != JoinAction::Leave;
  reply(command, answer, sender, writer, seated, now);
}

void ServerLoop::readCommands(double now) {
  for (auto& in : transport_.takeCommands(limits_)) {
    if (!in.request) {
      CommandAnswer refusal;
      refusal.seat = in.seat;
      refusal.seq = in.seq;
      refusal.rejection = {in.bad_signature ? Reject::BadSignature : Reject::Malformed, in.problem};
      refused(in.match, refusal, now, in.sender);  // logged escaped
      continue;
    }
    const CommandAnswer answer = registry_.shoot(*in.request, now);
    if (!answer.accepted()) {
      refused(in.match, answer, now, in.sender);
      continue;
    }
    ++counters_.commands_accepted;
    storeShot(answer, in.match);
    spdlog::info("command {} seat {} seq {}: accepted, shot {}", in.match, answer.seat, answer.seq,
                 answer.shot_number);
    publishResult(in.match, answer);
  }
  readPractice(now);
  if (auto summary = rejections_.summary(now)) spdlog::info("{}", *summary);
}

void ServerLoop::readPractice(double now) {
  for (auto& in : transport_.takePractice(limits_)) {
    if (!in.request) {
      CommandAnswer refusal;
      refusal.seat = in.seat;
      refusal.seq = in.seq;
      refusal.rejection = {in.bad_signature ? Reject::BadSignature : Reject::Malformed, in.problem};
      refused(in.match, refusal, now, in.sender);
      continue;
    }
    const CommandAnswer answer = registry_.practice(*in.request, now);
    if (!answer.accepted()) {
      refused(in.match, answer, now, in.sender);
      continue;
    }
    ++counters_.commands_accepted;
    spdlog::info("practice {} seat {} seq {}: {}", in.match, answer.seat, answer.seq,
                 protocol::toString(in.request->action));
    publishResult(in.match, answer);
  }
}

namespace {

/// The gate's view of `match` now.
AimTurn aimTurnOf(const Match& match, const MatchRegistry& registry) {
  AimTurn turn;
  turn.aiming = match.inPlay() && !match.inMotion() && !match.closed();
  if (!turn.aiming) return turn;
  turn.shooter = match.game().shooter;
  turn.shot_number = match.shotNumber();
  if (turn.shooter != 0 && turn.shooter != 1) return turn;
  const Seat& seat = match.seats()[static_cast<std::size_t>(turn.shooter)];
  turn.token = seat.token;
  turn.public_key = seat.public_key;
  turn.banned = registry.banReason(seat.public_key) != nullptr;
  return turn;
}

}  // namespace

void ServerLoop::relayAims(double now) {
  for (auto& read : transport_.takeAims()) {
    AimDrop drop = AimDrop::Malformed;
    if (read) {
      const Match* match = registry_.find(read->match);
      const AimTurn turn = match ? aimTurnOf(*match, registry_) : AimTurn{};
      drop = aims_.check(*read, match ? &turn : nullptr, now);
    } else {
      aims_.check(protocol::AimSample{}, nullptr, now);  // counted as malformed
    }
    if (drop != AimDrop::None) {
      spdlog::debug("aim {} seat {} seq {}: dropped ({})", read ? escapedForLog(read->match) : "?",
                    read ? read->seat : -1, read ? read->seq : 0, toString(drop));
      continue;
    }
    warnIfFailed(transport_.publish(*read), "aim");
  }
  // The drops are counted, not logged one by one: one line at most every 10 s while they come.
  const std::uint64_t dropped = aims_.droppedInAll();
  if (dropped != aims_seen_ && now - aims_logged_ >= 10.0) {
    aims_logged_ = now;
    aims_seen_ = dropped;
    std::string why;
    for (int i = 1; i < static_cast<int>(AimDrop::Count); ++i) {
      const auto d = static_cast<AimDrop>(i);
      if (!aims_.dropped(d)) continue;
      why += fmt::format("{}{} {}", why.empty() ? "" : ", ", toString(d), aims_.dropped(d));
    }
    spdlog::info("live aims: {} relayed, {} dropped ({})", aims_.relayed(), dropped, why);
  }
}

void ServerLoop::refused(const std::string& match, const CommandAnswer& answer, double now,
                         const std::string& sender) {
  spdlog::debug("command {} seat {} seq {}: {} ({})", escapedForLog(match), answer.seat, answer.seq,
                toString(answer.rejection.reason), escapedForLog(answer.rejection.text));
  rejections_.add(answer.rejection.reason, now);
  ++counters_.commands_refused;
  if (!ourSeat(match, answer.seat) && !stray_answers_.allow(sender, now))
    return;  // counted, not answered
  publishResult(match, answer);
}

bool ServerLoop::ourSeat(const std::string& match, int seat) const {
  return registry_.find(match) && (seat == 0 || seat == 1);
}

void ServerLoop::publishResult(const std::string& match, const CommandAnswer& answer) {
  const auto result = answer.done ? finalReport(match, *answer.done) : commandReport(match, answer);
  // A result keyed by a match or seat that does not exist is not kept for late readers: the
  // writer would otherwise hold one instance per made-up key for good.
  const bool keep = ourSeat(match, answer.seat);
  warnIfFailed(transport_.publish(result, keep), "shot result");
}

void ServerLoop::stepTournaments(double now) {
  tournaments_.step(now);
  for (const auto& view : tournaments_.takeChanged()) {
    warnIfFailed(transport_.publish(view), "tournament");
  }
}

void ServerLoop::answerHistory(double now) {
  auto requests = transport_.takeHistory();
  if (!history_) return;  // no store, no history: the requests are read and dropped
  for (const auto& in : requests) {
    std::string why;
    const auto shots = history_->answer(in, now, &why);
    if (!why.empty()) spdlog::debug("history request from {}: {}", in.sender, why);
    for (const auto& shot : shots) warnIfFailed(transport_.publish(shot), "history shot");
  }
}

void ServerLoop::stepReplay(double now) {
  if (!replay_ || replay_reported_) return;
  // A replay is for spectators: it starts once someone reads its results, so that nobody who
  // was there from the start misses its first shots to discovery.
  if (!replay_started_) {
    if (transport_.resultReaders(replay_->matchId()) == 0) return;
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
  // Practice tables are not kept: a restart ends them (server/README.md).
  if (!store_ || !answer.record || !m || m->practice()) return;
  double ms = 0.0;
  try {
    ms = timedCommit([&] {
      store_->recordShot(*answer.record, rules::describe(answer.record->verdict),
                         registry_.snapshotOf(*m));
    });
  } catch (const store::StoreError& e) {
    throw store::StoreError("storing shot " + std::to_string(answer.record->shot_number) + " of " +
                            match + ": " + e.what());
  }
  spdlog::info("stored shot {} of {} (seat {} seq {}) in {:.2f} ms", answer.record->shot_number,
               match, answer.seat, answer.seq, ms);
  // A record without a stroke (a choice, the clock run out) has no flight to wait for: the
  // players' records go out now; a stroke's once it is seen through (publishFrames).
  if (!answer.record->shoots) {
    for (const auto& error : players_.publishSeats(*store_, *m))
      warnIfFailed(error, "player stats");
  }
}

void ServerLoop::storeChanges(const std::vector<std::string>& closed) {
  if (!store_) return;
  std::vector<MatchSnapshot> changed;
  for (Match* m : registry_.matches()) {
    if (m->practice()) continue;  // not kept across restarts
    auto& stored = stored_[m->id()];
    if (stored == m->revision()) continue;
    stored = m->revision();
    changed.push_back(registry_.snapshotOf(*m));
  }
  for (const auto& id : closed) {
    stored_.erase(id);
    timedCommit([&] { store_->closeMatch(id); });
  }
  // A practice table is not stored, but its number is used: the counter is kept all the same,
  // so no id is given twice across a restart.
  if (!changed.empty() || registry_.opened() != stored_opened_) {
    stored_opened_ = registry_.opened();
    timedCommit([&] { store_->saveMatches(registry_.serverId(), registry_.opened(), changed); });
  }
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
      // The players' records once the stroke is seen through (stored with it, shown after it).
      if (store_ && !m->practice()) {
        for (const auto& error : players_.publishSeats(*store_, *m))
          warnIfFailed(error, "player stats");
      }
    }
  }
}

void ServerLoop::publishChanges(double now) {
  for (Match* m : registry_.matches()) {
    auto& published = published_[m->id()];
    if (published.revision != m->revision()) {
      published.revision = m->revision();
      warnIfFailed(transport_.publish(matchViewOf(*m, last_step_)), "match state");
    } else if (published.spectators == m->spectators() ||
               now - published.info_at < kSpectatorCountPeriod) {
      continue;  // at most one lobby entry a period for spectators coming and going
    }
    published.spectators = m->spectators();
    published.info_at = now;
    published.entry = lobbyEntryOf(*m, registry_.serverId());
    addRatings(*m, *published.entry);
    warnIfFailed(transport_.publish(*published.entry), "match info");
  }
}

void ServerLoop::addRatings(const Match& match, protocol::LobbyEntry& entry) {
  if (!store_) return;
  for (std::size_t s = 0; s < 2; ++s) {
    const auto& key = match.seats()[s].public_key;
    if (!match.seats()[s].taken() || key.empty()) continue;
    const double r = store::ratingOf(store_->database(), key, match.settings().game).rating;
    entry.ratings[s] = static_cast<int>(std::lround(r));
  }
}

void ServerLoop::dispose(const std::string& match) {
  spdlog::info("match {} closed", match);
  transport_.dispose(match);
  published_.erase(match);
  aims_.forget(match);
}

void ServerLoop::publishClosing(const std::string& match) {
  const auto it = published_.find(match);
  if (it == published_.end() || !it->second.entry ||
      it->second.entry->phase == protocol::MatchPhase::Closed) {
    return;
  }
  it->second.entry->phase = protocol::MatchPhase::Closed;
  warnIfFailed(transport_.publish(*it->second.entry), "match info");
}

void ServerLoop::disposeAll() {
  for (Match* m : registry_.matches()) dispose(m->id());
}

}  // namespace pool::server
