// Pinned server keys: first sight pins, the same key passes, another is refused, the file keeps
// them owner-only, forgetting rewrites it, server ids that could forge lines are refused, and a
// flood of made-up ids neither evicts a kept pin nor keeps a new server from being pinned.
#include <gtest/gtest.h>

#include <sys/stat.h>

#include <fstream>

#include "client/net/server_pins.h"
#include "support/child_process.h"

namespace pool::client::test {
namespace {

TEST(ServerPinsTest, FirstSightPinsAndAnotherKeyIsRefused) {
  ServerPins pins;
  const auto a = protocol::generateKeyPair();
  const auto b = protocol::generateKeyPair();
  EXPECT_EQ(pins.check("lab", a.public_key), PinCheck::FirstSight);
  EXPECT_EQ(pins.check("lab", a.public_key), PinCheck::Same);
  EXPECT_EQ(pins.check("lab", b.public_key), PinCheck::Changed);
  EXPECT_EQ(pins.check("other", b.public_key), PinCheck::FirstSight);
  EXPECT_TRUE(pins.forget("lab"));
  EXPECT_FALSE(pins.forget("lab"));
  EXPECT_EQ(pins.check("lab", b.public_key), PinCheck::FirstSight);
}

TEST(ServerPinsTest, TheFileKeepsPinsOwnerOnlyAndForgettingRewritesIt) {
  ScratchDir dir("pins");
  const std::filesystem::path path = dir.file("config/pool/servers");
  const auto a = protocol::generateKeyPair();
  const auto b = protocol::generateKeyPair();
  {
    ServerPins pins(path);
    EXPECT_EQ(pins.check("lab", a.public_key), PinCheck::FirstSight);
    EXPECT_EQ(pins.check("den", b.public_key), PinCheck::FirstSight);
    EXPECT_EQ(pins.fileProblem(), "");
  }
  struct stat st {};
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  {
    ServerPins pins(path);
    EXPECT_EQ(pins.check("lab", a.public_key), PinCheck::Same);
    EXPECT_EQ(pins.check("lab", b.public_key), PinCheck::Changed);
    EXPECT_TRUE(pins.forget("lab"));
  }
  ASSERT_EQ(::stat(path.c_str(), &st), 0);
  EXPECT_EQ(st.st_mode & 0777, 0600u);
  ServerPins pins(path);
  EXPECT_EQ(pins.pinned("lab"), nullptr);
  ASSERT_NE(pins.pinned("den"), nullptr);
  EXPECT_EQ(pins.check("den", b.public_key), PinCheck::Same);
}

TEST(ServerPinsTest, ServerIdsThatCouldForgeALineAreRefused) {
  ScratchDir dir("pins-bad");
  const std::filesystem::path path = dir.file("servers");
  const auto a = protocol::generateKeyPair();
  const auto evil = protocol::generateKeyPair();
  {
    ServerPins pins(path);
    EXPECT_EQ(pins.check("x 0000\nlab", evil.public_key), PinCheck::Refused);
    EXPECT_EQ(pins.check("", evil.public_key), PinCheck::Refused);
    EXPECT_EQ(pins.check(std::string(25, 'a'), evil.public_key), PinCheck::Refused);
    EXPECT_EQ(pins.check("lab", std::vector<std::uint8_t>(31, 1)), PinCheck::Refused);
    EXPECT_EQ(pins.check("lab", a.public_key), PinCheck::FirstSight);
  }
  // Lines that are not pins are skipped when the file is read.
  std::ofstream(path, std::ios::app) << "garbage\nden zz\n";
  ServerPins pins(path);
  EXPECT_EQ(pins.check("lab", a.public_key), PinCheck::Same);
  EXPECT_EQ(pins.pinned("den"), nullptr);
}

TEST(ServerPinsTest, AFloodOfNewIdsNeverEvictsAKeptPinAndANewServerIsStillPinned) {
  ServerPins pins;
  const auto real = protocol::generateKeyPair();
  const auto late = protocol::generateKeyPair();
  const auto evil = protocol::generateKeyPair();
  ASSERT_EQ(pins.check("srv", real.public_key), PinCheck::FirstSight);
  // 1 100 made-up ids: the pins kept for good fill up, the rest wait on probation.
  for (int i = 0; i < 1100; ++i) {
    ASSERT_EQ(pins.check("flood" + std::to_string(i), evil.public_key), PinCheck::FirstSight) << i;
  }
  EXPECT_FALSE(pins.onProbation("srv"));
  EXPECT_FALSE(pins.onProbation("flood1022"));
  EXPECT_TRUE(pins.onProbation("flood1023"));
  // A server seen first now is pinned (on probation) and its key checked.
  EXPECT_EQ(pins.check("late", late.public_key), PinCheck::FirstSight);
  EXPECT_TRUE(pins.onProbation("late"));
  EXPECT_EQ(pins.check("late", evil.public_key), PinCheck::Changed);
  // Thousands more made-up ids evict only probation pins, the ones that signed longest ago: a
  // server that keeps signing (here every 100 ids) stays pinned, the kept pins stay.
  for (int i = 1100; i < 5000; ++i) {
    pins.check("flood" + std::to_string(i), evil.public_key);
    if (i % 100 == 0) {
      ASSERT_EQ(pins.check("late", late.public_key), PinCheck::Same) << i;
    }
  }
  EXPECT_GT(pins.evicted(), 3000u);
  EXPECT_EQ(pins.check("late", late.public_key), PinCheck::Same);
  EXPECT_EQ(pins.check("srv", real.public_key), PinCheck::Same);
  EXPECT_EQ(pins.check("srv", evil.public_key), PinCheck::Changed);
  EXPECT_EQ(pins.pinned("flood1200"), nullptr) << "a probation pin that never signed again stays";
  // Once a kept pin is forgotten, the next probation pin to sign is kept for good.
  EXPECT_TRUE(pins.forget("flood5"));
  EXPECT_EQ(pins.check("late", late.public_key), PinCheck::Same);
  EXPECT_FALSE(pins.onProbation("late"));
}

}  // namespace
}  // namespace pool::client::test
