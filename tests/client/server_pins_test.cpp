// Pinned server keys: first sight pins, the same key passes, another is refused, the file keeps
// them owner-only, forgetting rewrites it, and server ids that could forge lines are refused.
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

}  // namespace
}  // namespace pool::client::test
