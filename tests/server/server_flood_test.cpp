// A participant flooding the server with bad commands, or with spectators that come and vanish,
// is answered each time, while other matches in motion keep their snapshot rate, the store is not
// written, the log stays short and the server's memory of clients goes back to where it was.
#include <gtest/gtest.h>

#include <sys/stat.h>
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <deque>
#include <fstream>
#include <regex>
#include <set>

#include <thread>

#include "net/protocol_topics.h"
#include "net/wire_fields.h"
#include "protocol/command_signature.h"
#include "server_fixture.h"
#include "support/child_process.h"
#include "support/sanitizer.h"
#include "support/spectate_request.h"

namespace pool::server::test {
constexpr bool kUnderAddressSanitizer = POOL_UNDER_ASAN;

namespace {

using Clock = std::chrono::steady_clock;

/// Frames of one shot as a subscriber received them.
struct ShotFrames {
  std::size_t received = 0;
  double span = 0.0;  ///< s between the first and last frame's publication (source timestamps)

  /// Frames per second of publication; 0 for fewer than two frames.
  double rate() const {
    return received > 1 && span > 0 ? static_cast<double>(received - 1) / span : 0.0;
  }
};

ShotFrames framesOf(const TestClient& watcher, const std::string& match, std::uint32_t shot) {
  ShotFrames out;
  std::int64_t first = 0;
  std::int64_t last = 0;
  for (const auto& s : watcher.snapshots) {
    if (net::textOf(s->match) != match || s->shot_number != shot) continue;
    const std::int64_t t = s.meta().source_time_ns;
    if (out.received++ == 0) first = last = t;
    first = std::min(first, t);
    last = std::max(last, t);
  }
  out.span = static_cast<double>(last - first) * 1e-9;
  return out;
}

/// Sends bad commands for "t-3" as fast as `per_second` allows, cycling through: unsigned with
/// seat 0's token, signed by the flooder's own key with seat 0's token (forged), seat 1's token on
/// seat 0 (the other seat's), and seat 1's token signed by the flooder (forged for seat 1).
class Flooder {
 public:
  Flooder(TestClient& client, const Seated& target, double per_second)
      : client_(client), target_(target), per_second_(per_second) {}
  ~Flooder() { stop(); }

  void start() {
    thread_ = std::thread([this] { run(); });
  }
  void stop() {
    stop_ = true;
    if (thread_.joinable()) thread_.join();
  }
  std::uint32_t sent() const { return sent_.load(); }
  double seconds() const { return seconds_; }

 private:
  void run() {
    const auto t0 = Clock::now();
    while (!stop_) {
      const std::uint32_t n = sent_.load();
      const auto due = t0 + std::chrono::duration<double>(n / per_second_);
      if (Clock::now() < due) std::this_thread::sleep_until(due);
      client_.send(*net::toWire(command(n)));
      sent_ = n + 1;
    }
    seconds_ = std::chrono::duration<double>(Clock::now() - t0).count();
  }

  protocol::ShotRequest command(std::uint32_t n) const {
    protocol::ShotRequest r;
    r.match = target_.match;
    r.seq = n + 1;  // always above the seat's last: only the signature check stops it
    r.cue.speed = 5.0;
    switch (n % 4) {
      case 0:
        r.seat_token = target_.token[0];
        break;
      case 1:
        r.seat_token = target_.token[0];
        protocol::signCommand(r, client_.key());
        break;
      case 2:
        r.seat_token = target_.token[1];
        protocol::signCommand(r, client_.key());
        break;
      default:
        r.seat = 1;
        r.seat_token = target_.token[1];
        protocol::signCommand(r, client_.key());
        break;
    }
    return r;
  }

  TestClient& client_;
  Seated target_;
  double per_second_;
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<std::uint32_t> sent_{0};
  double seconds_ = 0.0;
};

class ServerFlood : public ServerTest {};

/// Shoots the next shot in `match` as whoever is to shoot, once its state has `shot` shots.
void shootNext(TestClient& zero, TestClient& one, const Seated& s, std::uint32_t shot,
               std::uint32_t seq) {
  const auto* state = zero.waitState(
      s.match, [&](auto& st) { return st.shot_number == shot; }, 30s);
  ASSERT_NE(state, nullptr) << s.match << " never reached shot " << shot;
  ASSERT_TRUE(state->shooter == 0 || state->shooter == 1) << s.match << " is not in play";
  (state->shooter == 0 ? zero : one).send(anyLegalShot(*state, s, seq));
}

TEST_F(ServerFlood, EveryBadCommandIsRefusedAndOtherMatchesKeepTheirSnapshotRate) {
  // Info level: the refusals are counted in one line a second, not logged one by one.
  start(kFlood, {"--tables", "3", "--snapshot-hz", "60"}, "info");
  TestClient a(kFlood, "a"), b(kFlood, "b"), c(kFlood, "c"), d(kFlood, "d");
  TestClient e(kFlood, "e"), f(kFlood, "f"), x(kFlood, "flooder");
  for (TestClient* client : {&a, &b, &c, &d, &e, &f, &x}) {
    ASSERT_TRUE(client->waitForServer(3, 30s)) << client->id();
  }
  const Seated one = seat(a, b, "t-1");
  const Seated two = seat(c, d, "t-2");
  const Seated three = seat(e, f, "t-3");  // the flood's target: its players wait
  const auto joined = x.join(pool_JOIN_SPECTATE, "t-3");
  ASSERT_TRUE(joined && joined->outcome == pool_JOIN_ACCEPTED);
  const auto* target = e.waitState("t-3", [](auto& st) { return st.phase == pool_PHASE_BREAK; });
  ASSERT_NE(target, nullptr);
  const std::uint32_t target_revision = target->revision;

  // Without the flood: both matches break (shot 1), seen by `a`.
  a.send(breakShot(one, 0, 1));
  c.send(breakShot(two, 0, 1));
  ASSERT_NE(a.waitFinal("t-1", 0, 1, 60s), nullptr);
  ASSERT_NE(c.waitFinal("t-2", 0, 1, 60s), nullptr);

  // With it: shot 2 of both matches.
  Flooder flood(x, three, 4000.0);
  flood.start();
  std::this_thread::sleep_for(500ms);
  shootNext(a, b, one, 1, 2);
  shootNext(c, d, two, 1, 2);
  for (const auto& [watcher_of, match_id] : {std::pair{&a, "t-1"}, std::pair{&c, "t-2"}}) {
    // Plain copies: clang 14 cannot capture structured bindings in a lambda.
    auto* watcher = watcher_of;
    const char* match = match_id;
    const bool done = watcher->waitUntil(
        [&] {
          const auto* st = watcher->latestState(match);
          return st && st->shot_number >= 2;
        },
        90s);
    EXPECT_TRUE(done) << match << " did not finish shot 2 under the flood";
  }
  flood.stop();
  a.waitUntil([] { return false; }, 300ms);  // the last frames in flight

  double base = 0;
  double flooded = 0;
  for (const char* match : {"t-1", "t-2"}) {
    const ShotFrames calm = framesOf(a, match, 1);
    const ShotFrames busy = framesOf(a, match, 2);
    std::printf(
        "%s: without flood %zu frames in %.2f s = %.1f/s; with flood %zu frames in %.2f s "
        "= %.1f/s\n",
        match, calm.received, calm.span, calm.rate(), busy.received, busy.span, busy.rate());
    ASSERT_GT(calm.span, 0.5) << match << ": the break moved too briefly to measure";
    ASSERT_GT(busy.span, 0.3) << match << ": shot 2 moved too briefly to measure";
    base += calm.rate() / 2;
    flooded += busy.rate() / 2;
  }

  // Every answer the flooder got is a refusal with its reason; the target match did not move.
  std::size_t answers = 0;
  std::set<pool_RejectReason> reasons;
  x.waitUntil([] { return false; }, 500ms);
  for (const auto& r : x.results) {
    if (net::textOf(r->match) != "t-3") continue;
    ++answers;
    EXPECT_FALSE(r->accepted) << "seq " << r->seq;
    EXPECT_NE(r->reject_text[0], '\0');
    reasons.insert(r->reject_reason);
  }
  for (const auto reason : reasons) {
    EXPECT_TRUE(reason == pool_REJECT_UNSIGNED || reason == pool_REJECT_BAD_SIGNATURE ||
                reason == pool_REJECT_BAD_TOKEN)
        << "unexpected reason " << reason;
  }
  const auto* after = e.latestState("t-3");
  ASSERT_NE(after, nullptr);
  EXPECT_EQ(after->revision, target_revision) << "the flood changed its target match";
  EXPECT_EQ(after->shot_number, 0u);

  // The server's own count of refusals (one summary line a second, so the last one comes up to a
  // second after the flood): every command sent, each refused.
  const auto refusedSoFar = [&] {
    std::uint64_t n = 0;
    const std::string log = server_->log();
    const std::regex line("refused (\\d+) shot commands");
    for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator();
         ++it) {
      n += std::stoull((*it)[1]);
    }
    return n;
  };
  // The server may still be working through the flood's backlog (under the sanitizers, checking
  // each signature takes longer than the flood took to send): the wait goes on while the count
  // grows, and ends 15 s after it last grew (at most 5 minutes in all).
  std::uint64_t refused = refusedSoFar();
  auto grew = Clock::now();
  for (const auto cap = Clock::now() + 300s;
       refused < flood.sent() && Clock::now() - grew < 15s && Clock::now() < cap;) {
    std::this_thread::sleep_for(100ms);
    const std::uint64_t now_refused = refusedSoFar();
    if (now_refused > refused) grew = Clock::now();
    refused = now_refused;
  }
  std::printf(
      "flood: %u commands in %.2f s (%.0f/s); the server refused %llu; the flooder "
      "received %zu answers\n",
      flood.sent(), flood.seconds(), static_cast<double>(flood.sent()) / flood.seconds(),
      static_cast<unsigned long long>(refused), answers);
  std::printf(
      "snapshot rate of the other matches: %.1f/s without, %.1f/s with the flood (%.0f %%)\n", base,
      flooded, 100.0 * flooded / base);
  // A flood: commands several times faster than the match's 60 frames a second, each needing its
  // signature checked; how far beyond that the sender gets is the machine's.
  EXPECT_GT(static_cast<double>(flood.sent()) / flood.seconds(), 5.0 * 60.0) << "not a flood";
  EXPECT_GT(answers, 0u);
  EXPECT_EQ(reasons.size(), 3u) << "unsigned, forged and other-seat commands each get theirs";
  EXPECT_EQ(refused, flood.sent());
  // 60 frames a second are paced to the wall clock, so matches the flood does not hold back keep
  // their calm rate. Half of it is the margin for the flooding client sharing the server's two
  // cores, under the sanitizers too; the server's 60 Hz capacity itself is measured by
  // net_bench's BM_SixtyHzCapacity, not here.
  EXPECT_GE(flooded, 0.5 * base);
}

/// Spectators that each ask to watch `match` once, as fast as `per_second` allows, each with a
/// client id of its own, from `writers` writers of one participant in turn (so that neither the
/// client id nor the writer names the flood), and vanish with those writers at the end of each
/// flood (a client's presence is its writer's: the writers go right after the last request, so
/// the server may read requests after their writer is gone).
class SpectatorFlooder {
 public:
  SpectatorFlooder(std::uint32_t domain, std::string match, std::size_t writers)
      : bus_(domain), match_(std::move(match)), count_(writers) {}

  /// Makes the writers and waits for the server's reader to match them.
  bool waitForServer() {
    for (std::size_t i = writers_.size(); i < count_; ++i) {
      writers_.emplace_back(bus_.participant, bus_.join_request_topic, net::qos::joinRequest());
    }
    return std::all_of(writers_.begin(), writers_.end(),
                       [](const auto& w) { return w.waitForReaders(1, 15s); });
  }

  /// Sends `count` spectators at `per_second`, then deletes the writers; returns the seconds it
  /// took.
  double flood(std::uint32_t count, double per_second) {
    EXPECT_TRUE(waitForServer());
    const auto t0 = Clock::now();
    for (std::uint32_t i = 0; i < count; ++i) {
      const auto due = t0 + std::chrono::duration<double>(i / per_second);
      if (Clock::now() < due) std::this_thread::sleep_until(due);
      EXPECT_TRUE(writers_[i % writers_.size()].write(
          *pool::test::spectateRequest("watcher-" + std::to_string(next_++), match_, 1)));
    }
    const double seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    writers_.clear();
    return seconds;
  }

 private:
  net::ProtocolTopics bus_;
  std::deque<net::Writer<pool_JoinRequest>> writers_;
  std::string match_;
  std::size_t count_;
  std::uint32_t next_ = 0;
};

/// The server's last summary of joins: spectators accepted in all summaries so far, and the
/// watching and tracked counts of the last one (-1 before any).
struct JoinSummaries {
  std::uint64_t spectators = 0;
  std::uint64_t over_limit = 0;  ///< requests dropped over their participant's limit
  long watching = -1;
  long tracked = -1;
  std::size_t lines = 0;
};

JoinSummaries joinSummaries(const std::string& log) {
  JoinSummaries out;
  const std::regex line(
      R"(joins and leaves in [0-9.]+ s: (.*) \((\d+) watching, (\d+) clients tracked\))");
  const std::regex accepted(R"(spectate accepted (\d+))");
  const std::regex limited(R"(over the per-participant limit (\d+))");
  for (auto it = std::sregex_iterator(log.begin(), log.end(), line); it != std::sregex_iterator();
       ++it) {
    ++out.lines;
    const std::string what = (*it)[1];
    std::smatch n;
    if (std::regex_search(what, n, accepted)) out.spectators += std::stoull(n[1]);
    if (std::regex_search(what, n, limited)) out.over_limit += std::stoull(n[1]);
    out.watching = std::stol((*it)[2]);
    out.tracked = std::stol((*it)[3]);
  }
  return out;
}

/// The last line of `log` that starts with `prefix` (from it), or "" when there is none.
std::string lastLine(const std::string& log, const std::string& prefix) {
  const auto at = log.rfind(prefix);
  if (at == std::string::npos) return "";
  return log.substr(at, log.find('\n', at) - at);
}

/// Size and modification time of every file of the database (the file, its journal or WAL).
std::string storeFiles(const std::string& db) {
  std::string out;
  for (const char* suffix : {"", "-wal", "-journal", "-shm"}) {
    struct stat st {};
    if (::stat((db + suffix).c_str(), &st) != 0) continue;
    out += db + suffix + " " + std::to_string(st.st_size) + " " +
           std::to_string(st.st_mtim.tv_sec) + "." + std::to_string(st.st_mtim.tv_nsec) + "\n";
  }
  return out;
}

TEST_F(ServerFlood, SpectatorsFloodingInAndVanishingCostNoStoreNoLogAndLeaveNothingBehind) {
  pool::client::test::ScratchDir scratch("join-flood");
  const std::string db = scratch.file("pool.db");
  start(kJoinFlood, {"--tables", "2", "--snapshot-hz", "60", "--db", db}, "info");
  TestClient a(kJoinFlood, "a"), b(kJoinFlood, "b");
  ASSERT_TRUE(a.waitForServer(2, 30s));
  ASSERT_TRUE(b.waitForServer(2, 30s));
  SpectatorFlooder flooder(kJoinFlood, "t-2", 20);  // the other table: the one being played is t-1
  ASSERT_TRUE(flooder.waitForServer());
  const Seated one = seat(a, b, "t-1");

  // Without the flood: the break (shot 1). A few spectators set the baseline of what is tracked.
  a.send(breakShot(one, 0, 1));
  ASSERT_NE(a.waitFinal("t-1", 0, 1, 60s), nullptr);
  const auto settled = [&](std::uint64_t spectators) {
    JoinSummaries s;
    a.waitUntil(
        [&] {
          s = joinSummaries(server_->log());
          return s.spectators + s.over_limit >= spectators && s.watching == 0;
        },
        60s);
    return s;
  };
  flooder.flood(10, 100.0);
  const JoinSummaries baseline = settled(10);
  ASSERT_EQ(baseline.watching, 0) << "ten spectators came and went";
  const double rss_before = residentMb(server_->pid());
  const std::size_t log_before = server_->log().size();

  // Three floods of 2 000 spectators a second; shot 2 of t-1 moves during the first.
  constexpr std::uint32_t kPerFlood = 6000;
  constexpr double kRate = 2000.0;
  // What a flood may leave resident: DDS's own caches of samples and instances (bounded), the
  // heap's high-water pages not yet given back. Three floods with every spectator answered left
  // 28–40 MB here; the bound catches that.
  constexpr double kRssSlackMb = 4.0;
  std::uint64_t expected = 10;
  std::printf("server RSS %.1f MB before the floods; %ld clients tracked\n", rss_before,
              baseline.tracked);
  double seconds = 0.0;
  {
    std::thread shot([&] { shootNext(a, b, one, 1, 2); });
    seconds = flooder.flood(kPerFlood, kRate);
    shot.join();
  }
  std::string stored;  // the store's files once shot 2 is stored and at rest
  std::uint64_t answered_before = baseline.spectators;
  for (int n = 1; n <= 3; ++n) {
    if (n == 2) {
      // Shot 2 is anyLegalShot's 8 m/s safety, paced to the wall clock: it may roll for half a
      // minute.
      ASSERT_TRUE(a.waitUntil(
          [&] {
            const auto* st = a.latestState("t-1");
            return st && st->shot_number >= 2;
          },
          90s));
      a.waitUntil([] { return false; }, 200ms);  // the state is stored before it is published
      stored = storeFiles(db);
    }
    // (The first flood ran beside shot 2 above: it started from the baseline.)
    const double rss_start = n == 1 ? rss_before : residentMb(server_->pid());
    if (n > 1) seconds = flooder.flood(kPerFlood, kRate);
    expected += kPerFlood;
    const double rss_flooded = residentMb(server_->pid());
    const JoinSummaries after = settled(expected);
    // Once the flood is over (2 s without joins) the server gives the freed heap back.
    const auto trims = [&] {
      const std::string log = server_->log();
      std::size_t count = 0;
      for (auto at = log.find("a flood is over"); at != std::string::npos;
           at = log.find("a flood is over", at + 1)) {
        ++count;
      }
      return count;
    };
    EXPECT_TRUE(a.waitUntil([&] { return trims() >= static_cast<std::size_t>(n); }, 30s))
        << "no trim after flood " << n;
    const double rss_after = residentMb(server_->pid());
    std::printf(
        "flood %d: %u spectators in %.2f s (%.0f/s) from 20 writers of one participant; the server "
        "counted %llu accepted and %llu over the participant's limit in all, %ld watching and %ld "
        "clients tracked "
        "after it; RSS %.1f MB before it, %.1f MB at its end, %.1f MB once it was over (%s)\n",
        n, kPerFlood, seconds, kPerFlood / seconds,
        static_cast<unsigned long long>(after.spectators),
        static_cast<unsigned long long>(after.over_limit), after.watching, after.tracked, rss_start,
        rss_flooded, rss_after, lastLine(server_->log(), "a flood is over").c_str());
    // Every request is counted, answered or dropped over its participant's limit; the
    // participant, asking under 6 000 client ids from 20 writers, is answered as one client of
    // twice the rate (40 at once, 20 a second: server_loop.h), so its spectators cost the server
    // next to nothing.
    EXPECT_EQ(after.spectators + after.over_limit, expected) << "every request is counted";
    const auto answered = after.spectators - answered_before;
    answered_before = after.spectators;
    EXPECT_LE(static_cast<double>(answered), 40.0 + 20.0 * (seconds + 1.0))
        << "a participant asking under many client ids and writers is limited as one";
    EXPECT_GT(answered, 0u);
    if (n == 1) {
      // The participant is told why, in a reply to one of its client ids (any reader sees it).
      const bool told = a.waitUntil([&] {
        return std::any_of(a.replies.begin(), a.replies.end(), [](const auto& r) {
          return std::string(net::textOf(r->client)).rfind("watcher-", 0) == 0 &&
                 std::string(net::textOf(r->reason)).find("from one DDS participant") !=
                     std::string::npos;
        });
      });
      EXPECT_TRUE(told) << "the flooding participant was never told why it went unanswered";
    }
    // Memory back to its baseline once each flood is over. Under AddressSanitizer freed memory
    // waits in its quarantine: the server's RSS says nothing of its own, so the bound holds for
    // the normal build only (the figures are printed anyway).
    if (!kUnderAddressSanitizer) {
      EXPECT_LE(rss_after, rss_before + kRssSlackMb) << "the flood's memory stayed";
    }
    EXPECT_EQ(after.watching, 0) << "every spectator that vanished is noticed";
    // What the server still tracks once the flood is over, as that line says: the last summary
    // of joins can come in the flood's last second, while its clients' join buckets are still
    // being refilled (161 tracked, once, beside the sanitized suite).
    const std::string over = lastLine(server_->log(), "a flood is over");
    const auto tracked_at = over.find(" clients tracked");
    ASSERT_NE(tracked_at, std::string::npos) << over;
    const long tracked_after = std::stol(over.substr(over.rfind(' ', tracked_at - 1) + 1));
    EXPECT_LE(tracked_after, baseline.tracked) << "the server still holds clients of the flood";
  }

  // Nothing durable changed for spectators in floods 2 and 3, and the log grew by summaries, not
  // a line each.
  EXPECT_EQ(storeFiles(db), stored) << "spectators were written to the store";
  const std::string log = server_->log().substr(log_before);
  const auto lines = std::count(log.begin(), log.end(), '\n');
  std::printf("the floods added %ld log lines for %u spectators\n", static_cast<long>(lines),
              3 * kPerFlood);
  EXPECT_LT(lines, 200) << log.substr(0, 2000);

  // The match in play went on: shot 2 moved at its paced rate during the first flood.
  const ShotFrames calm = framesOf(a, "t-1", 1);
  const ShotFrames busy = framesOf(a, "t-1", 2);
  std::printf("t-1's frame rate: %.1f/s without, %.1f/s during the join flood (%.0f %%)\n",
              calm.rate(), busy.rate(), 100.0 * busy.rate() / calm.rate());
  ASSERT_GT(calm.span, 0.5) << "the break moved too briefly to measure";
  // Shot 2 is the 8 m/s safety of anyLegalShot, which moves for seconds; a shot that published
  // under 0.3 s of frames during the flood is a match the flood held back.
  ASSERT_GT(busy.span, 0.3) << "shot 2 moved too briefly to measure during the join flood";
  // Frames are paced to the wall clock at 60 a second, so a match the flood does not hold back
  // keeps its calm rate. The flooding client runs beside the server on the same cores, at 2 000
  // joins a second, in the sanitized build too: half the calm rate is the margin for that
  // machine's share, not a throughput figure.
  EXPECT_GE(busy.rate(), 0.5 * calm.rate());
}

TEST_F(ServerFlood, AClientAskingTooOftenIsToldToWaitAndOthersAreNot) {
  start(kJoinRate, {"--tables", "1", "--fast"});
  TestClient eager(kJoinRate, "eager"), calm(kJoinRate, "calm");
  ASSERT_TRUE(eager.waitForServer());
  ASSERT_TRUE(calm.waitForServer());
  // Sixty requests at once: the burst of twenty (and what refills while they arrive) is
  // answered, the rest are told to wait. Replies to one client replace each other on the wire
  // (keep-last 1), so only the last is sure to arrive; every one that does is counted.
  std::size_t accepted = 0, limited = 0;
  const std::size_t from = eager.replies.size();
  std::uint32_t last = 0;
  const auto t0 = Clock::now();
  for (int i = 0; i < 60; ++i) {
    const protocol::SeatRequest r = eager.request(pool_JOIN_SPECTATE, "t-1");
    last = r.request;
    eager.writeJoin(*pool::test::spectateRequest(r.client, r.match, r.request));
  }
  const double elapsed = std::chrono::duration<double>(Clock::now() - t0).count();
  ASSERT_TRUE(eager.waitUntil([&] {
    for (std::size_t i = from; i < eager.replies.size(); ++i) {
      if (eager.replies[i]->request == last) return true;
    }
    return false;
  })) << "the last request was not answered";
  for (std::size_t i = from; i < eager.replies.size(); ++i) {
    const auto& r = eager.replies[i];
    if (net::textOf(r->client) != "eager") continue;
    if (r->outcome == pool_JOIN_ACCEPTED) ++accepted;
    if (r->outcome == pool_JOIN_NOT_ALLOWED &&
        std::string(net::textOf(r->reason)).find("too many join requests") != std::string::npos) {
      ++limited;
    }
  }
  std::printf("60 requests in %.3f s: %zu answered, %zu told to wait\n", elapsed, accepted,
              limited);
  // Twenty at once, ten a second after that; the server reads them at most 0.5 s later.
  EXPECT_LE(static_cast<double>(accepted), 20.0 + 10.0 * (elapsed + 0.5));
  EXPECT_GE(limited, 20u) << "sixty at once is far over ten a second";
  // Another client is not held back by the eager one.
  const auto reply = calm.join(pool_JOIN_SPECTATE, "t-1");
  ASSERT_TRUE(reply.has_value());
  EXPECT_EQ(reply->outcome, pool_JOIN_ACCEPTED);
  // Once its bucket has refilled, the eager client is answered again.
  std::this_thread::sleep_for(1s);
  const auto later = eager.join(pool_JOIN_SPECTATE, "t-1");
  ASSERT_TRUE(later.has_value());
  EXPECT_EQ(later->outcome, pool_JOIN_ACCEPTED);
}

}  // namespace
}  // namespace pool::server::test
