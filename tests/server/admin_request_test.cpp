// The admin request's checks: every verb's fields, refusals with their reasons, and the round trip.
#include "server/admin/admin_request.h"

#include <gtest/gtest.h>

#include "server/admin/admin_cli.h"

namespace pool::admin {
namespace {

std::string refusal(const std::string& line) {
  const auto parsed = parseRequest(line);
  EXPECT_FALSE(parsed) << line;
  return parsed ? std::string() : parsed.error();
}

TEST(AdminRequest, EachVerbReadsItsFields) {
  const std::string key(64, 'A');
  auto ban = parseRequest(R"({"verb":"ban","key":")" + key + R"(","reason":"cheating, Zoë"})");
  ASSERT_TRUE(ban) << ban.error();
  EXPECT_EQ(ban->verb, Verb::Ban);
  ASSERT_EQ(ban->key.size(), 32u);
  EXPECT_EQ(ban->key[0], 0xAA);
  EXPECT_EQ(ban->reason, "cheating, Zoë");
  auto close = parseRequest(R"({"verb":"close","match":"ab12-3","reason":"late"})");
  ASSERT_TRUE(close);
  EXPECT_EQ(close->match, "ab12-3");
  auto backup = parseRequest(R"({"verb":"backup","path":"/var/lib/pool/copy.db"})");
  ASSERT_TRUE(backup);
  EXPECT_EQ(backup->path, "/var/lib/pool/copy.db");
  for (const char* verb : {"status", "list", "bans"}) {
    EXPECT_TRUE(parseRequest(std::string(R"({"verb":")") + verb + "\"}")) << verb;
  }
  // What requestLine writes, parseRequest reads back the same.
  auto again = parseRequest(requestLine(*ban));
  ASSERT_TRUE(again);
  EXPECT_EQ(again->key, ban->key);
  EXPECT_EQ(again->reason, ban->reason);
}

TEST(AdminRequest, BadInputIsRefusedWithItsReason) {
  EXPECT_EQ(refusal("ban everyone"), "not a JSON object");
  EXPECT_EQ(refusal("[]"), "not a JSON object");
  EXPECT_EQ(refusal(R"({"key":"00"})"), "verb: missing");
  EXPECT_EQ(refusal(R"({"verb":"drop tables"})"),
            "verb: 'drop tables' is not one of status, list, close, ban, unban, bans, backup");
  EXPECT_EQ(refusal(R"({"verb":"list","match":"t-1"})"), "match: not a field of list");
  EXPECT_EQ(refusal(R"({"verb":"close","match":"t-1"})"), "reason: missing (close needs it)");
  EXPECT_EQ(refusal(R"({"verb":"close","match":7,"reason":"x"})"), "match: must be a string");
  EXPECT_EQ(refusal(R"({"verb":"close","match":"","reason":"x"})"), "match: 1-39 printable bytes");
  EXPECT_EQ(refusal(R"({"verb":"close","match":"t-1\n","reason":"x"})"),
            "match: 1-39 printable bytes");
  EXPECT_EQ(refusal(R"({"verb":"close","match":"t-1","reason":"a\u001bb"})"),
            "reason: 1-120 bytes of UTF-8 without control characters");
  EXPECT_EQ(refusal(R"({"verb":"close","match":"t-1","reason":")" + std::string(121, 'r') + "\"}"),
            "reason: 1-120 bytes of UTF-8 without control characters");
  EXPECT_EQ(refusal(R"({"verb":"unban","key":")" + std::string(62, 'a') + "\"}"),
            "key: an Ed25519 public key is 64 hex digits");
  EXPECT_EQ(refusal(R"({"verb":"unban","key":")" + std::string(63, 'a') + "g\"}"),
            "key: an Ed25519 public key is 64 hex digits");
  EXPECT_EQ(refusal(R"({"verb":"backup","path":"copy.db"})"),
            "path: an absolute path without control characters");
  EXPECT_EQ(refusal(std::string(kMaxRequestBytes + 1, ' ')), "request longer than 8192 bytes");
  // Not UTF-8 at all: the JSON reader refuses it.
  EXPECT_EQ(refusal("{\"verb\":\"ban\",\"key\":\"\xff\"}"), "not a JSON object");
}

TEST(AdminCommandLine, TheSocketIsBesideTheDatabase) {
  EXPECT_EQ(socketPathFor("/var/lib/pool/pool.db"), "/var/lib/pool/pool.db.sock");
  const char* serve[] = {"pool-server", "--db", "x.db"};
  const char* status[] = {"pool-server", "status"};
  const char* admin[] = {"pool-server", "admin", "list"};
  EXPECT_FALSE(isAdminCommand(3, serve));
  EXPECT_TRUE(isAdminCommand(2, status));
  EXPECT_TRUE(isAdminCommand(3, admin));
}

}  // namespace
}  // namespace pool::admin
