// Integration-test fixture: a real pool-server on a test's own domain, seated players, shots.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <numbers>
#include <string>
#include <vector>

#include "server_process.h"
#include "support/domain_claim.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"
#include "test_client.h"

namespace pool::server::test {

/// Server integration tests use DDS domains 100–119, one per test, never shared (ctest runs them
/// in parallel, and two servers with one id on one domain answer each other's clients).
enum Domain : std::uint32_t {
  kBreakFlow = 100,
  kRejections,
  kSpectator,
  kTwoMatches,
  kSigterm,
  kRejoin,
  kForfeit,
  kJoinRefusals,
  kNewMatch,
  kSideBySide,
  kSeatAttacks,
  kVersionMismatch,  ///< its own: two servers under one id on one domain refuse to run
  kAdmin,
  kAdminBackup,
  kStoreDeleted,
  kStoreDeletedIdle,
};

/// The flood tests' domain (135–149 are theirs).
inline constexpr std::uint32_t kFlood = 135;
inline constexpr std::uint32_t kJoinFlood = 137;  ///< 136 is a client test's
inline constexpr std::uint32_t kJoinRate = 138;

/// Two players seated in one match.
struct Seated {
  std::string match;
  std::uint64_t token[2] = {0, 0};
};

/// Starts pool-server in SetUp-called start(); prints its log when a test failed.
class ServerTest : public ::testing::Test {
 protected:
  void SetUp() override { useLoopbackConfig(); }
  void TearDown() override {
    if (server_ && HasFailure()) std::cerr << "---- pool-server log ----\n" << server_->log();
  }

  /// Starts the server on `domain` with server id "t", `args` and `log_level`.
  void start(std::uint32_t domain, std::vector<std::string> args,
             const std::string& log_level = "debug") {
    pool::test::claimDomain(claim_, domain);
    pool::test::requireClaim(*claim_);
    args.insert(args.end(), {"--server-id", "t", "--log-level", log_level});
    server_ = std::make_unique<ServerProcess>(domain, args);
    ASSERT_GT(server_->pid(), 0);
  }

  /// Seats `a` in seat 0 and `b` in seat 1 of `match`.
  static Seated seat(TestClient& a, TestClient& b, const std::string& match) {
    Seated s;
    s.match = match;
    const auto ra = a.join(pool_JOIN_SEAT, match, "Ada", 0);
    const auto rb = b.join(pool_JOIN_SEAT, match, "Bob", 1);
    EXPECT_TRUE(ra && ra->outcome == pool_JOIN_ACCEPTED);
    EXPECT_TRUE(rb && rb->outcome == pool_JOIN_ACCEPTED);
    if (ra) s.token[0] = ra->seat_token;
    if (rb) s.token[1] = rb->seat_token;
    return s;
  }

  std::unique_ptr<pool::test::DomainClaim> claim_;  // released after the server stops
  std::unique_ptr<ServerProcess> server_;
};

/// A firm break up the table from where the server racks the cue ball.
inline protocol::ShotRequest breakShot(const Seated& s, int seat, std::uint32_t seq) {
  protocol::ShotRequest r;
  r.match = s.match;
  r.seat = seat;
  r.seat_token = s.token[seat];
  r.seq = seq;
  r.cue.speed = 8.0;
  r.cue.tip_height = 0.1;
  return r;
}

/// A slow roll toward the head cushion, hitting nothing: about two seconds of motion.
inline protocol::ShotRequest softShot(const Seated& s, int seat, std::uint32_t seq) {
  protocol::ShotRequest r = breakShot(s, seat, seq);
  r.cue.yaw = std::numbers::pi;
  r.cue.speed = 0.3;
  r.cue.tip_height = 0.0;
  return r;
}

/// A safety by whoever is to shoot in `state`: the first offered choice that shoots, the cue
/// ball placed behind the head string when it is in hand, at 8 m/s toward the cushion point
/// farthest from every pocket, so that it moves for seconds wherever the rack's break left it
/// (yaw 0 from a cue ball resting by a foot corner drops it in the pocket within a few frames).
inline protocol::ShotRequest anyLegalShot(const pool_MatchState& state, const Seated& s,
                                          std::uint32_t seq) {
  protocol::ShotRequest r = breakShot(s, state.shooter, seq);
  r.safety = true;
  for (std::uint32_t i = 0; i < state.options._length && r.option == protocol::ShotOption::None;
       ++i) {
    const auto option = net::fromWire(state.options._buffer[i]);
    if (option && protocol::optionShoots(*option)) r.option = *option;
  }
  const bool in_hand =
      state.ball_in_hand != pool_IN_HAND_NONE || r.option == protocol::ShotOption::BallInHand;
  Eigen::Vector2d from(-0.9, 0.3);
  if (in_hand) {
    // The first of a few places behind the head string that no ball covers (a break can leave a
    // ball anywhere, the kitchen included: a covered place is refused as an illegal placement).
    for (const Eigen::Vector2d& at : {Eigen::Vector2d(-0.9, 0.3), Eigen::Vector2d(-0.9, -0.3),
                                      Eigen::Vector2d(-1.0, 0.0), Eigen::Vector2d(-0.75, 0.45),
                                      Eigen::Vector2d(-0.75, -0.45), Eigen::Vector2d(-1.1, 0.4)}) {
      bool clear = true;
      for (std::uint32_t i = 0; i < state.balls._length; ++i) {
        const auto& b = state.balls._buffer[i];
        const bool on_table = b.state != pool_MOTION_POCKETED && b.state != pool_MOTION_OFF_TABLE;
        if (b.id != 0 && on_table && (Eigen::Vector2d(b.pos.x, b.pos.y) - at).norm() < 0.07)
          clear = false;
      }
      if (clear) {
        from = at;
        break;
      }
    }
    r.cue_ball_at = from;
  } else {
    for (std::uint32_t i = 0; i < state.balls._length; ++i) {
      const auto& b = state.balls._buffer[i];
      if (b.id == 0) from = Eigen::Vector2d(b.pos.x, b.pos.y);
    }
  }
  // The 9-ft table (TableSpec's defaults, as the server's wpa-9ft); each of 72 directions is
  // followed to the cushion it meets.
  const table::TableGeometry table = table::buildTableGeometry(table::TableSpec{});
  const double hx = table.length / 2;
  const double hy = table.width / 2;
  double best = -1.0;
  for (int k = 0; k < 72; ++k) {
    const double yaw = k * std::numbers::pi / 36;
    const Eigen::Vector2d d(std::cos(yaw), std::sin(yaw));
    const double tx = d.x() > 1e-9    ? (hx - from.x()) / d.x()
                      : d.x() < -1e-9 ? (-hx - from.x()) / d.x()
                                      : 1e9;
    const double ty = d.y() > 1e-9    ? (hy - from.y()) / d.y()
                      : d.y() < -1e-9 ? (-hy - from.y()) / d.y()
                                      : 1e9;
    const Eigen::Vector2d hit = from + std::min(tx, ty) * d;
    double clear = 1e9;
    for (const auto& hole : table.holes) clear = std::min(clear, (hit - hole.centre).norm());
    if (clear > best) {
      best = clear;
      r.cue.yaw = yaw;
    }
  }
  return r;
}

inline bool isFinal(const pool_ShotResult& r) {
  return r.accepted && r.verdict_text[0] != '\0';
}

}  // namespace pool::server::test
