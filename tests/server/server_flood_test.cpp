// A participant flooding the server with bad commands is refused each time, with its reasons,
// while two other matches in motion keep their snapshot rate.
#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <regex>
#include <set>
#include <thread>

#include "net/wire_fields.h"
#include "protocol/command_signature.h"
#include "server_fixture.h"

namespace pool::server::test {
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
  std::uint64_t refused = refusedSoFar();
  for (const auto until = Clock::now() + 15s; refused < flood.sent() && Clock::now() < until;) {
    std::this_thread::sleep_for(100ms);
    refused = refusedSoFar();
  }
  std::printf(
      "flood: %u commands in %.2f s (%.0f/s); the server refused %llu; the flooder "
      "received %zu answers\n",
      flood.sent(), flood.seconds(), static_cast<double>(flood.sent()) / flood.seconds(),
      static_cast<unsigned long long>(refused), answers);
  std::printf(
      "snapshot rate of the other matches: %.1f/s without, %.1f/s with the flood (%.0f %%)\n", base,
      flooded, 100.0 * flooded / base);
  EXPECT_GT(static_cast<double>(flood.sent()) / flood.seconds(), 1000.0) << "not a flood";
  EXPECT_GT(answers, 0u);
  EXPECT_EQ(reasons.size(), 3u) << "unsigned, forged and other-seat commands each get theirs";
  EXPECT_EQ(refused, flood.sent());
  // 60 frames a second are paced to the wall clock; a 10 % margin absorbs the scheduling noise
  // of a loaded machine, not a server that falls behind.
  EXPECT_GE(flooded, 0.9 * base);
}

}  // namespace
}  // namespace pool::server::test
