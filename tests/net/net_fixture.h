// Test helpers for the transport: loopback config, one DDS domain per test, sample builders.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <string>
#include <vector>

#include "net/messages.h"
#include "net/participant.h"
#include "net/reader.h"
#include "net/waitset.h"
#include "net/wire_fields.h"
#include "physics/ball.h"

namespace pool::net::test {

using namespace std::chrono_literals;

/// Net tests use DDS domains 150–199, one per test (ctest runs tests in parallel).
enum Domain : std::uint32_t {
  kRoundTripLobby = 150,
  kRoundTripJoin,
  kRoundTripCommand,
  kRoundTripResult,
  kRoundTripSnapshot,
  kRoundTripState,
  kLateJoiner,
  kKeepAll,
  kBestEffort,
  kDispose,
  kWaitSetGuard,
  kTwoProcesses,
  kLiveliness,
  kMalformedOnWire,
  kTakeEach,
  kReadCache,
  kLateReply,
  kConstruction,
  kDisposeBeforeTake,
  kClosingEntry,
};

/// Points Cyclone at the loopback-only configuration; call before creating participants.
inline void useLoopbackConfig() {
  const std::string uri = std::string("file://") + POOL_SOURCE_DIR + "/assets/cyclone-lo.xml";
  ::setenv("CYCLONEDDS_URI", uri.c_str(), 1);
}

/// Takes from `reader` until `count` data samples arrived or `timeout` passed.
template <class T>
std::vector<Sample<T>> takeAtLeast(const Participant& participant, const Reader<T>& reader,
                                   std::size_t count, std::chrono::milliseconds timeout = 5s) {
  WaitSet waitset(participant);
  waitset.attachData(reader, 1);
  std::vector<Sample<T>> got;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (got.size() < count && std::chrono::steady_clock::now() < deadline) {
    waitset.wait(50ms);
    for (auto& s : reader.take()) {
      got.push_back(std::move(s));
    }
  }
  return got;
}

/// A ball with every field set to something distinct (and non-trivial doubles).
inline physics::Ball oddBall(int id) {
  physics::Ball b;
  b.id = id;
  b.pos = {0.1 * id + 1.0 / 3.0, -0.2 * id - 1e-17, 0.028575};
  b.orient = physics::Quat(0.5, -0.5, 0.5, 0.5 + 1e-12 * id);
  b.vel = {1.0 / 7.0, -2.5, 1e-300};
  b.ang_vel = {-3.0 / 11.0, 42.0, -0.0};
  b.state = id % 2 ? physics::MotionState::Rolling : physics::MotionState::Sliding;
  return b;
}

/// Fixture: loopback config set, tests name their domain.
class NetTest : public ::testing::Test {
 protected:
  void SetUp() override { useLoopbackConfig(); }
};

}  // namespace pool::net::test
