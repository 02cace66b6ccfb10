// Benchmark: the network path on loopback against a real pool-server. Accepted shot to first
// snapshot (p50, p99), snapshot bytes per second per subscriber while balls move, and how many
// matches one server core keeps publishing at 60 Hz with every table moving.
#include <benchmark/benchmark.h>
#include <sched.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_run.h"
#include "net/convert.h"
#include "net/match_partition.h"
#include "net/message_convert.h"
#include "net/participant.h"
#include "net/partition.h"
#include "net/protocol_topics.h"
#include "net/qos_profiles.h"
#include "net/reader.h"
#include "net/server_seal.h"
#include "net/topic.h"
#include "net/waitset.h"
#include "net/wire_fields.h"
#include "net/writer.h"
#include "protocol/command_signature.h"
#include "protocol/key_pair.h"
#include "protocol/server_signature.h"
#include "server/match/join_rate_limit.h"
#include "support/partitions.h"

namespace {

using namespace pool;
using Clock = std::chrono::steady_clock;
using namespace std::chrono_literals;

double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

/// Seconds since the Unix epoch: the clock DDS stamps samples with (source timestamps).
double wallNow() {
  return std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch()).count();
}

double percentile(std::vector<double> v, double p) {
  if (v.empty()) return NAN;
  std::sort(v.begin(), v.end());
  const auto i = static_cast<std::size_t>(std::ceil(p * static_cast<double>(v.size()))) - 1;
  return v[std::min(i, v.size() - 1)];
}

/// pool-server as a child process pinned to one CPU; killed in the destructor.
class PinnedServer {
 public:
  PinnedServer(std::uint32_t domain, int tables, int cpu) {
    std::vector<std::string> argv{std::string(POOL_BIN_DIR) + "/pool-server",
                                  "--domain",
                                  std::to_string(domain),
                                  "--tables",
                                  std::to_string(tables),
                                  "--server-id",
                                  "bench",
                                  "--log-level",
                                  "warn",
                                  "--db",
                                  db_};
    std::vector<char*> raw;
    for (auto& a : argv) raw.push_back(a.data());
    raw.push_back(nullptr);
    cpu_set_t set;
    CPU_ZERO(&set);
    CPU_SET(cpu, &set);
    pid_ = ::fork();
    if (pid_ == 0) {
      ::sched_setaffinity(0, sizeof set, &set);
      ::execv(raw[0], raw.data());
      ::_exit(127);
    }
  }
  ~PinnedServer() {
    ::kill(pid_, SIGKILL);
    ::waitpid(pid_, nullptr, 0);
    for (const char* suffix : {"", "-wal", "-shm"}) std::remove((db_ + suffix).c_str());
  }
  PinnedServer(const PinnedServer&) = delete;
  PinnedServer& operator=(const PinnedServer&) = delete;

  /// CPU time the server has used so far (user + system), s.
  double cpuSeconds() const {
    std::ifstream in("/proc/" + std::to_string(pid_) + "/stat");
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::istringstream fields(text.substr(text.rfind(')') + 2));
    std::string f;
    double ticks = 0;
    for (int i = 3; i <= 15 && fields >> f; ++i) {
      if (i == 14 || i == 15) ticks += std::stod(f);
    }
    return ticks / static_cast<double>(::sysconf(_SC_CLK_TCK));
  }

 private:
  std::string db_ = "/tmp/pool-net-bench-" + std::to_string(::getpid()) + ".db";
  pid_t pid_ = -1;
};

/// One match driven by the benchmark: both seats, the latest state, the shot in flight.
struct Table {
  std::string match;
  std::array<std::uint64_t, 2> tokens{0, 0};
  std::array<std::uint32_t, 2> seq{0, 0};
  std::optional<protocol::MatchView> state;
  // The shot in flight (client clock, s).
  std::uint32_t shot = 0;
  double sent = -1, accepted = -1, first_frame = -1;
  double accepted_at_server = -1;  ///< source timestamp of the acceptance (wall clock, s)
  std::vector<std::pair<double, double>> arrivals;  ///< (arrival, sim_time) of each frame
  bool done = true;
  std::uint32_t frames = 0;
  double bytes = 0;
  double last_frame = -1;
};

/// XCDR2 size of a TableSnapshot sample (DHEADERs of the appendable struct and of the sequence of
/// structs; 8-byte values aligned to 4), the payload each subscriber receives per frame.
std::size_t snapshotBytes(const pool_TableSnapshot& s) {
  auto align = [](std::size_t n, std::size_t a) { return (n + a - 1) / a * a; };
  std::size_t n = 4;                         // DHEADER
  n += 4 + net::textOf(s.match).size() + 1;  // match
  n = align(n, 4) + 4 + 8 + 4;               // frame, sim_time, shot_number
  n += 4 + 4;                                // DHEADER and length of balls
  for (const auto& b : net::elementsOf(s.balls)) {
    n = align(n, 4) + 1;                        // id
    n = align(n, 4) + 4 + 13 * 8;               // state, pos, orient, vel, ang_vel
    n += 4 + net::textOf(b.pocket).size() + 1;  // pocket
  }
  return n;
}

/// A benchmark client that drives every table of one server: seats, shots, frames.
class Driver {
 public:
  explicit Driver(std::uint32_t domain)
      : bus_(domain),
        lobby_(bus_.participant, bus_.match_info_topic, net::qos::lobby()),
        replies_(bus_.participant, bus_.join_reply_topic, net::qos::joinReply()),
        every_match_(bus_.participant, test::everyPartition()),
        results_(every_match_, bus_.result_topic, deep(net::qos::result())),
        snapshots_(every_match_, bus_.snapshot_topic, deep(net::qos::snapshot())),
        states_(every_match_, bus_.state_topic, deep(net::qos::state())),
        requests_(bus_.participant, bus_.join_request_topic, net::qos::joinRequest()),
        commands_(bus_.participant, bus_.command_topic, net::qos::command()),
        waitset_(bus_.participant) {
    waitset_.attachData(lobby_, 1);
    waitset_.attachData(replies_, 2);
    waitset_.attachData(results_, 3);
    waitset_.attachData(snapshots_, 4);
    waitset_.attachData(states_, 5);
  }

  /// Waits for `n` matches in the lobby and takes both seats of each. False on timeout.
  bool seatAll(std::size_t n, std::chrono::seconds timeout) {
    const auto t0 = Clock::now();
    while (tables_.size() < n && Clock::now() - t0 < timeout) {
      waitset_.wait(20ms);
      for (auto& s : lobby_.take()) {
        const std::string id(net::textOf(s->match));
        if (!tables_.count(id)) tables_[id].match = id;
      }
    }
    // Seat requests and commands are volatile: one written before the server's reader matched
    // ours is lost. The lobby reaching us says nothing of that match (another pair of endpoints),
    // so wait for it; on a loaded machine it can come seconds after the lobby.
    while ((requests_.publicationMatched().current < 1 ||
            commands_.publicationMatched().current < 1) &&
           Clock::now() - t0 < timeout) {
      std::this_thread::sleep_for(10ms);
    }
    // One participant may ask 2 x kBurst at once and 2 x kPerSecond a second after (the server
    // refuses the rest unread): the driver asks for a hundred tables' seats at a pace it keeps.
    constexpr double kBurst = server::JoinRateLimit::kBurst,
                     kRate = server::JoinRateLimit::kPerSecond;
    const auto paced_from = Clock::now();
    int request = 0;
    for (auto& [id, t] : tables_) {
      for (int seat = 0; seat < 2; ++seat) {
        if (request >= kBurst) {
          std::this_thread::sleep_until(
              paced_from + std::chrono::duration_cast<Clock::duration>(
                               std::chrono::duration<double>((request - kBurst + 1) / kRate)));
        }
        protocol::SeatRequest r;
        r.client = clientOf(id, seat);
        r.request = static_cast<std::uint32_t>(++request);
        r.protocol_version = protocol::kProtocolVersion;
        r.match = id;
        r.action = protocol::JoinAction::Seat;
        r.seat = seat;
        r.name = "p" + std::to_string(seat);
        r.seq = ++seq_;
        protocol::signSeatRequest(r, key_);
        requests_.write(*net::toWire(r));
      }
    }
    std::size_t seated = 0;
    while (seated < 2 * tables_.size() && Clock::now() - t0 < timeout) {
      waitset_.wait(20ms);
      for (auto& s : replies_.take()) {
        auto answer = net::fromWire(*s);
        if (!answer || !answer->accepted() || !tables_.count(answer->match)) continue;
        tables_[answer->match].tokens[static_cast<std::size_t>(answer->seat)] = answer->token;
        ++seated;
      }
      pollStates();
    }
    return seated == 2 * tables_.size() && waitStates(timeout);
  }

  /// Sends one shot on every table: the break (hard) or a gentle safety, from its state.
  void shootAll(bool hard) {
    for (auto& [id, t] : tables_) {
      if (!t.state || !protocol::inPlay(t.state->phase)) continue;
      send(t, hard);
    }
  }

  /// Sends one gentle shot on `match` only.
  void shootOne(const std::string& match) {
    auto it = tables_.find(match);
    if (it != tables_.end() && it->second.state && protocol::inPlay(it->second.state->phase)) {
      send(it->second, false);
    }
  }

  /// Receives until every table's shot is done (final result and a state after it), or timeout,
  /// or `window` s of frames (then stops counting: the capacity run measures a window).
  void pumpShots(std::chrono::seconds timeout, double window = 1e9) {
    const auto t0 = Clock::now();
    while (Clock::now() - t0 < timeout && secondsSince(t0) < window + 1.0 && !allDone()) {
      waitset_.wait(5ms);
      pollResults();
      pollFrames();
      pollStates();
      // Unread lobby entries or replies would keep the waitset awake (a busy loop).
      lobby_.take();
      replies_.take();
      if (secondsSince(t0) > window) break;
    }
  }

  std::map<std::string, Table>& tables() { return tables_; }
  std::vector<double>& latencies() { return latencies_; }
  std::vector<double>& roundTrips() { return round_trips_; }
  std::vector<double>& commandToFrame() { return command_to_frame_; }
  Clock::time_point epoch() const { return epoch_; }

 private:
  static net::QosProfile deep(net::QosProfile p) {
    p.history_depth = 4096;
    return p;
  }
  static std::string clientOf(const std::string& match, int seat) {
    return "bench-" + match + "-" + std::to_string(seat);
  }
  double now() const { return secondsSince(epoch_); }

  bool waitStates(std::chrono::seconds timeout) {
    const auto t0 = Clock::now();
    auto ready = [&] {
      return std::all_of(tables_.begin(), tables_.end(), [](const auto& kv) {
        return kv.second.state && protocol::inPlay(kv.second.state->phase);
      });
    };
    while (!ready() && Clock::now() - t0 < timeout) {
      waitset_.wait(20ms);
      pollStates();
    }
    return ready();
  }

  bool allDone() const {
    return std::all_of(tables_.begin(), tables_.end(), [](const auto& kv) {
      const Table& t = kv.second;
      return t.done && t.state && t.state->shot_number >= t.shot;
    });
  }

  void send(Table& t, bool hard) {
    const protocol::MatchView& s = *t.state;
    const auto seat = static_cast<std::size_t>(s.shooter < 0 ? 0 : s.shooter);
    protocol::ShotRequest r;
    r.match = t.match;
    r.seat = static_cast<int>(seat);
    r.seat_token = t.tokens[seat];
    r.seq = ++t.seq[seat];
    r.cue.speed_is_ball = true;
    auto in_hand = s.ball_in_hand;
    if (!s.options.empty()) {
      const auto& o = s.options;
      auto offered = [&](rules::Choice c) { return std::find(o.begin(), o.end(), c) != o.end(); };
      r.option = offered(rules::Choice::PlayOn)       ? protocol::ShotOption::PlayOn
                 : offered(rules::Choice::BallInHand) ? protocol::ShotOption::BallInHand
                                                      : protocol::ShotOption::ReBreak;
      if (r.option == protocol::ShotOption::BallInHand)
        in_hand = rules::BallInHand::BehindHeadString;
    }
    if (hard && s.phase == protocol::MatchPhase::Break) {
      // The break: full on the apex from just behind the head string.
      r.cue_ball_at = Eigen::Vector2d(-0.645, 0.0);
      r.cue.yaw = 0.0;
      r.cue.speed = 9.0;
    } else {
      // A gentle roll toward the head cushion: the cue ball alone moves for about a second.
      if (in_hand != rules::BallInHand::None) r.cue_ball_at = Eigen::Vector2d(-0.9, 0.3);
      r.cue.yaw = M_PI;
      r.cue.speed = 0.2;
      r.safety = s.phase != protocol::MatchPhase::Break;
    }
    t.sent = now();
    t.accepted = t.first_frame = t.last_frame = t.accepted_at_server = -1;
    t.arrivals.clear();
    t.done = false;
    t.shot = s.shot_number + 1;
    protocol::signCommand(r, key_);
    commands_.write(*net::toWire(r));
  }

  void pollStates() {
    for (auto& s : states_.take()) {
      auto view = net::fromWire(*s);
      if (view && tables_.count(view->match)) tables_[view->match].state = std::move(*view);
    }
  }

  void pollResults() {
    for (auto& s : results_.take()) {
      const std::string id(net::textOf(s->match));
      if (!tables_.count(id)) continue;
      Table& t = tables_[id];
      if (!s->accepted) {
        t.done = true;  // rejected (should not happen): the round goes on without it
        continue;
      }
      const bool final = net::textOf(s->verdict_text).size() > 0 || s->events._length > 0;
      if (!final && t.accepted < 0) {
        t.accepted = now();
        t.accepted_at_server = 1e-9 * static_cast<double>(s.meta().source_time_ns);
        round_trips_.push_back(t.accepted - t.sent);
      }
      if (final) {
        t.done = true;
        t.shot = s->shot_number;
      }
    }
  }

  void pollFrames() {
    snapshots_.takeEach(
        [&](const pool_TableSnapshot& s, const net::SampleMeta&) {
          const double at = now();
          const double wall = wallNow();
          const std::string id(net::textOf(s.match));
          auto it = tables_.find(id);
          if (it == tables_.end() || s.shot_number != it->second.shot) return;
          Table& t = it->second;
          ++t.frames;
          t.bytes += static_cast<double>(snapshotBytes(s));
          t.last_frame = at;
          t.arrivals.emplace_back(at, s.sim_time);
          if (t.first_frame < 0) {
            t.first_frame = at;
            // From the server's acceptance (its timestamp) to our receipt, on one host's clock.
            if (t.accepted_at_server > 0) latencies_.push_back(wall - t.accepted_at_server);
            if (t.sent >= 0) command_to_frame_.push_back(at - t.sent);
          }
        },
        4096);
  }

  net::ProtocolTopics bus_;  ///< the participant and the protocol's topics
  net::Reader<pool_MatchInfo> lobby_;
  net::Reader<pool_JoinReply> replies_;
  net::Subscriber every_match_;  ///< the driver plays every table: it follows every match
  net::Reader<pool_ShotResult> results_;
  net::Reader<pool_TableSnapshot> snapshots_;
  net::Reader<pool_MatchState> states_;
  net::Writer<pool_JoinRequest> requests_;
  net::Writer<pool_ShotCommand> commands_;
  protocol::KeyPair key_ =
      protocol::generateKeyPair();  ///< every seat's, for the driver plays them all
  std::uint32_t seq_ = 0;           ///< the key's seat requests, numbered
  net::WaitSet waitset_;
  std::map<std::string, Table> tables_;
  std::vector<double> latencies_, round_trips_, command_to_frame_;
  Clock::time_point epoch_ = Clock::now();
};

/// What one client receives of the server's per-match topics in `partitions`: the bytes of every
/// state, result and frame its readers take (each sample's XCDR2 encoding and its 64-byte
/// signature), as a client's readers (net/client_transport) would take them.
class Listener {
 public:
  Listener(std::uint32_t domain, const std::vector<std::string>& partitions)
      : bus_(domain),
        subscriber_(bus_.participant, partitions),
        results_(subscriber_, bus_.result_topic, deep(net::qos::result())),
        snapshots_(subscriber_, bus_.snapshot_topic, deep(net::qos::snapshot())),
        states_(subscriber_, bus_.state_topic, deep(net::qos::state())) {}

  /// Takes what arrived and counts it.
  void drain() {
    for (auto& s : results_.take(1 << 16)) count(*s);
    for (auto& s : states_.take(1 << 16)) count(*s);
    for (auto& s : snapshots_.take(1 << 16)) count(*s);
  }
  double bytes() const { return bytes_; }
  double samples() const { return samples_; }
  void reset() { bytes_ = samples_ = 0; }

 private:
  static net::QosProfile deep(net::QosProfile p) {
    p.history_depth = 8192;
    return p;
  }
  template <class T>
  void count(const T& sample) {
    bytes_ += static_cast<double>(net::sealedOf(sample).body.size() + protocol::kSignatureBytes);
    samples_ += 1;
  }

  net::ProtocolTopics bus_;
  net::Subscriber subscriber_;
  net::Reader<pool_ShotResult> results_;
  net::Reader<pool_TableSnapshot> snapshots_;
  net::Reader<pool_MatchState> states_;
  double bytes_ = 0, samples_ = 0;
};

void useLoopback() {
  const std::string uri = std::string("file://") + POOL_SOURCE_DIR + "/assets/cyclone-lo.xml";
  ::setenv("CYCLONEDDS_URI", uri.c_str(), 1);
}

// Domains 220-229 belong to this benchmark.
std::uint32_t nextDomain() {
  static std::uint32_t runs = 0;
  return 220 + runs++ % 10;
}

/// Accepted shot -> first snapshot on loopback, over a few rounds of gentle shots on 8 tables of
/// a paced (60 Hz) server; and the snapshot bytes per second one subscriber receives per match.
void BM_ShotToFirstSnapshot(benchmark::State& state) {
  useLoopback();
  const int tables = pool::bench::smokeOr(8, 2), rounds = pool::bench::smokeOr(6, 1);
  for (auto _ : state) {
    const std::uint32_t domain = nextDomain();
    PinnedServer server(domain, tables, 0);
    Driver driver(domain);
    if (!driver.seatAll(static_cast<std::size_t>(tables), 20s)) {
      state.SkipWithError("could not seat every table");
      return;
    }
    double bytes = 0, moving = 0;
    for (int r = 0; r < rounds; ++r) {
      driver.shootAll(false);
      driver.pumpShots(20s);
      for (auto& [id, t] : driver.tables()) {
        bytes += t.bytes;
        if (t.first_frame >= 0 && t.last_frame > t.first_frame)
          moving += t.last_frame - t.first_frame;
        t.bytes = 0;
        t.frames = 0;
      }
    }
    const auto& lat = driver.latencies();
    state.counters["samples"] = static_cast<double>(lat.size());
    state.counters["first_snapshot_p50_ms"] = 1e3 * percentile(lat, 0.5);
    state.counters["first_snapshot_p99_ms"] = 1e3 * percentile(lat, 0.99);
    state.counters["command_to_accepted_p50_ms"] = 1e3 * percentile(driver.roundTrips(), 0.5);
    state.counters["command_to_first_snapshot_p50_ms"] =
        1e3 * percentile(driver.commandToFrame(), 0.5);
    state.counters["snapshot_bytes_per_s_per_match"] = moving > 0 ? bytes / moving : 0;
    std::printf(
        "accepted -> first snapshot: p50 %.3f ms, p99 %.3f ms over %zu shots; "
        "snapshots %.0f B/s per subscriber per moving match\n",
        1e3 * percentile(lat, 0.5), 1e3 * percentile(lat, 0.99), lat.size(),
        moving > 0 ? bytes / moving : 0.0);
  }
}
BENCHMARK(BM_ShotToFirstSnapshot)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

/// N matches break at once on a server pinned to one core (publishing paced at 60 Hz); the
/// subscriber measures how late frames arrive against the simulated clock over a window of
/// motion. A server keeping up has a p99 lag under one frame (16.7 ms) and loses no frames.
void BM_SixtyHzCapacity(benchmark::State& state) {
  useLoopback();
  const int tables = static_cast<int>(state.range(0));
  constexpr double kWindow = 3.0;  // s of motion measured (every break moves longer)
  constexpr double kWarmUp = 1.0;  // s of motion skipped first
  for (auto _ : state) {
    const std::uint32_t domain = nextDomain();
    PinnedServer server(domain, tables, 0);
    Driver driver(domain);
    if (!driver.seatAll(static_cast<std::size_t>(tables), 60s)) {
      state.SkipWithError("could not seat every table");
      return;
    }
    driver.shootAll(true);
    driver.pumpShots(30s, kWarmUp);
    const double cpu0 = server.cpuSeconds();
    const auto steady_at = Clock::now();
    driver.pumpShots(30s, kWindow);
    const double cpu_share = (server.cpuSeconds() - cpu0) / secondsSince(steady_at);
    // Steady state: after the warm-up (every break simulated at once on acceptance), each frame's
    // lateness against the table's best (arrival - simulated time), and the frame rate.
    std::vector<double> lags;
    double frames = 0, span = 0;
    for (auto& [id, t] : driver.tables()) {
      std::vector<std::pair<double, double>> steady;
      for (const auto& a : t.arrivals) {
        if (a.second >= kWarmUp) steady.push_back(a);
      }
      if (steady.size() < 2) continue;
      double best = 1e9;
      for (const auto& [at, sim] : steady) best = std::min(best, at - sim);
      for (const auto& [at, sim] : steady) lags.push_back(at - sim - best);
      frames += static_cast<double>(steady.size() - 1);
      span += steady.back().second - steady.front().second;
    }
    const double lag99 = percentile(lags, 0.99);
    const double rate = span > 0 ? frames / span : 0.0;  // received frames per simulated second
    state.counters["tables"] = tables;
    state.counters["lag_p50_ms"] = 1e3 * percentile(lags, 0.5);
    state.counters["lag_p99_ms"] = 1e3 * lag99;
    state.counters["frames_per_s_per_match"] = rate;
    state.counters["keeps_60hz"] = lag99 < 1.0 / 60 && rate > 0.95 * 60 ? 1 : 0;
    state.counters["server_core_pct"] = 100.0 * cpu_share;
    state.counters["matches_per_core_at_60hz"] = cpu_share > 0 ? tables / cpu_share : 0;
    std::printf(
        "%d tables on one core: frame lateness p50 %.2f ms p99 %.2f ms, %.1f frames/s "
        "per match received, server uses %.0f%% of its core (%.0f matches per core)\n",
        tables, 1e3 * percentile(lags, 0.5), 1e3 * lag99, rate, 100.0 * cpu_share,
        cpu_share > 0 ? tables / cpu_share : 0.0);
  }
}

/// The bytes a spectator of one match receives while 100 other matches move beside it, against
/// the same spectator while only its own match moves (goal: at most 1.2 times as much). One real
/// pool-server (pinned to one core) with 101 tables, every seat played by the driver, each
/// round a gentle shot (about a second of frames at 60 Hz, then result and state) on its own
/// table alone, then on all 101 at once. The spectator subscribes as pool-client does since
/// protocol 5 (its match's partition); a listener to every match's partition (a wildcard) is
/// what every client received before partitions.
void BM_SpectatorBesideMovingMatches(benchmark::State& state) {
  useLoopback();
  const int kOthers = pool::bench::smokeOr(100, 3), kRounds = pool::bench::smokeOr(3, 1);
  for (auto _ : state) {
    const std::uint32_t domain = nextDomain();
    PinnedServer server(domain, kOthers + 1, 0);
    Driver driver(domain);
    if (!driver.seatAll(static_cast<std::size_t>(kOthers + 1), 90s)) {
      state.SkipWithError("could not seat every table");
      return;
    }
    const std::string own = driver.tables().begin()->first;
    Listener spectator(domain, {*net::matchPartition(own)});
    Listener everything(domain, {std::string(net::kMatchPartitionPrefix) + "*"});
    std::this_thread::sleep_for(500ms);  // discovery of the listeners' readers
    spectator.drain();
    everything.drain();
    spectator.reset();
    everything.reset();

    // Rounds of shots; the listeners drain after each (their readers keep a deep history).
    const auto rounds = [&](bool all) {
      const auto t0 = Clock::now();
      for (int r = 0; r < kRounds; ++r) {
        if (all) {
          driver.shootAll(false);
        } else {
          driver.shootOne(own);
        }
        driver.pumpShots(60s);
        spectator.drain();
        everything.drain();
      }
      return secondsSince(t0);
    };
    const double alone_s = rounds(false);
    const double alone = spectator.bytes() / alone_s;
    const double alone_all = everything.bytes() / alone_s;
    spectator.reset();
    everything.reset();
    const double beside_s = rounds(true);
    const double beside = spectator.bytes() / beside_s;
    const double before = everything.bytes() / beside_s;
    const double ratio = alone > 0 ? beside / alone : 0.0;
    state.counters["own_match_alone_B_per_s"] = alone;
    state.counters["beside_100_B_per_s"] = beside;
    state.counters["ratio"] = ratio;
    state.counters["every_match_listener_B_per_s"] = before;
    std::printf(
        "spectator of one match: %.0f B/s with only its match moving (a listener to every "
        "match: %.0f B/s), %.0f B/s beside %d moving matches: %.2fx (goal <= 1.2x); a listener "
        "to every match, as every client was before partitions, receives %.0f B/s beside them "
        "(%.0fx); rounds of %.1f s alone, %.1f s with all moving\n",
        alone, alone_all, beside, kOthers, ratio, before, alone > 0 ? before / alone : 0.0,
        alone_s / kRounds, beside_s / kRounds);
  }
}
BENCHMARK(BM_SpectatorBesideMovingMatches)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);

void capacityArgs(benchmark::internal::Benchmark* b) {
  // POOL_NET_BENCH_TABLES="25,50,100,200" sweeps; the default checks the target only.
  const char* env = std::getenv("POOL_NET_BENCH_TABLES");
  std::stringstream list(env ? env : pool::bench::smoke() ? "4" : "100");
  std::string item;
  while (std::getline(list, item, ',')) b->Arg(std::stol(item));
}
BENCHMARK(BM_SixtyHzCapacity)
    ->Apply(capacityArgs)
    ->Iterations(1)
    ->UseRealTime()
    ->Unit(benchmark::kSecond);

}  // namespace

int main(int argc, char** argv) {
  pool::bench::CheckedReporter reporter;
  return pool::bench::runBenchmarks(argc, argv, reporter);
}
