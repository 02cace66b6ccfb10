// The admin request's checks: every verb's fields, refusals with their reasons, and the round trip.
#include "server/admin/admin_request.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <map>
#include <string>
#include <utility>
#include <vector>

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
            "verb: 'drop tables' is not one of status, list, close, ban, unban, bans, backup, "
            "tournament-create, tournament-start, tournament-cancel, tournaments");
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

TEST(AdminRequest, TournamentVerbsReadTheirFieldsAndWriteThemBack) {
  auto create = parseRequest(
      R"({"verb":"tournament-create","name":"Spring Open, Zoë","format":"double","game":9,)"
      R"("race":5,"entrants":16})");
  ASSERT_TRUE(create) << create.error();
  EXPECT_EQ(create->verb, Verb::TournamentCreate);
  EXPECT_EQ(create->name, "Spring Open, Zoë");
  EXPECT_EQ(create->format, "double");
  EXPECT_EQ(create->game, 9);
  EXPECT_EQ(create->race, 5);
  EXPECT_EQ(create->entrants, 16);
  auto again = parseRequest(requestLine(*create));
  ASSERT_TRUE(again) << again.error();
  EXPECT_EQ(again->verb, Verb::TournamentCreate);
  EXPECT_EQ(again->name, create->name);
  EXPECT_EQ(again->format, create->format);
  EXPECT_EQ(again->game, create->game);
  EXPECT_EQ(again->race, create->race);
  EXPECT_EQ(again->entrants, create->entrants);
  EXPECT_FALSE(again->handicap) << "left out: no handicap";
  // A handicap is a yes or no, and crosses back.
  auto handicapped =
      parseRequest(R"({"verb":"tournament-create","name":"H","format":"single","game":9,"race":5,)"
                   R"("entrants":8,"handicap":true})");
  ASSERT_TRUE(handicapped) << handicapped.error();
  EXPECT_TRUE(handicapped->handicap);
  EXPECT_TRUE(parseRequest(requestLine(*handicapped))->handicap);
  EXPECT_EQ(refusal(R"({"verb":"tournament-create","name":"H","format":"single","game":9,)"
                    R"("race":5,"entrants":8,"handicap":1})"),
            "handicap: must be true or false");
  EXPECT_EQ(refusal(R"({"verb":"tournaments","handicap":true})"),
            "handicap: not a field of tournaments");
  // Every format and game, and the bounds of race and entrants.
  for (const char* format : {"single", "double", "round-robin"}) {
    for (int game : {8, 9, 10, 3, 22}) {
      const AdminRequest r{.verb = Verb::TournamentCreate,
                           .name = "Cup",
                           .format = format,
                           .game = game,
                           .race = 15,
                           .entrants = 32};
      auto read = parseRequest(requestLine(r));
      ASSERT_TRUE(read) << requestLine(r) << ": " << read.error();
      EXPECT_EQ(read->format, format);
      EXPECT_EQ(read->game, game);
    }
  }
  EXPECT_TRUE(parseRequest(
      R"({"verb":"tournament-create","name":"C","format":"single","game":8,"race":1,"entrants":3})"));
  EXPECT_TRUE(parseRequest(R"({"verb":"tournament-create","name":")" + std::string(31, 'n') +
                           R"(","format":"single","game":8,"race":1,"entrants":3})"));

  for (auto [verb, name] : {std::pair{Verb::TournamentStart, "tournament-start"},
                            std::pair{Verb::TournamentCancel, "tournament-cancel"}}) {
    auto read = parseRequest(std::string(R"({"verb":")") + name + R"(","tournament":"ab12-t3"})");
    ASSERT_TRUE(read) << name << ": " << read.error();
    EXPECT_EQ(read->verb, verb);
    EXPECT_EQ(read->tournament, "ab12-t3");
    EXPECT_EQ(requestLine(*read),
              std::string(R"({"tournament":"ab12-t3","verb":")") + name + "\"}");
    auto back = parseRequest(requestLine(*read));
    ASSERT_TRUE(back);
    EXPECT_EQ(back->verb, verb);
    EXPECT_EQ(back->tournament, "ab12-t3");
  }
  auto list = parseRequest(R"({"verb":"tournaments"})");
  ASSERT_TRUE(list);
  EXPECT_EQ(list->verb, Verb::Tournaments);
  EXPECT_EQ(requestLine(*list), R"({"verb":"tournaments"})");
  EXPECT_STREQ(toString(Verb::TournamentCreate), "tournament-create");
  EXPECT_STREQ(toString(Verb::Tournaments), "tournaments");
}

TEST(AdminRequest, TournamentFieldsOutOfRangeAreRefused) {
  // A create request with one field replaced.
  auto create = [](const std::string& field, const std::string& value) {
    std::map<std::string, std::string> fields{{"name", R"("Cup")"},
                                              {"format", R"("single")"},
                                              {"game", "8"},
                                              {"race", "1"},
                                              {"entrants", "8"}};
    if (value.empty()) {
      fields.erase(field);
    } else {
      fields[field] = value;
    }
    std::string line = R"({"verb":"tournament-create")";
    for (const auto& [k, v] : fields) line += ",\"" + k + "\":" + v;
    return line + "}";
  };
  EXPECT_TRUE(parseRequest(create("race", "3"))) << create("race", "3");
  EXPECT_EQ(refusal(create("format", R"("triple")")),
            "format: 'triple' is not one of single, double, round-robin");
  EXPECT_EQ(refusal(create("format", "1")), "format: must be a string");
  EXPECT_EQ(refusal(create("game", "7")), "game: 7 is not a game (8, 9, 10, 3 or 22)");
  EXPECT_EQ(refusal(create("game", R"("8")")), "game: must be a whole number");
  EXPECT_EQ(refusal(create("game", "8.5")), "game: must be a whole number");
  EXPECT_EQ(refusal(create("race", "0")), "race: 1-15 racks");
  EXPECT_EQ(refusal(create("race", "16")), "race: 1-15 racks");
  EXPECT_EQ(refusal(create("race", "-1")), "race: 1-15 racks");
  EXPECT_EQ(refusal(create("race", "18446744073709551615")), "race: 1-15 racks");
  EXPECT_EQ(refusal(create("entrants", "2")), "entrants: 3-32");
  EXPECT_EQ(refusal(create("entrants", "33")), "entrants: 3-32");
  EXPECT_EQ(refusal(create("name", R"("Cup\u0007")")),
            "name: 1-31 bytes of UTF-8 without control characters");
  EXPECT_EQ(refusal(create("name", R"("")")),
            "name: 1-31 bytes of UTF-8 without control characters");
  EXPECT_EQ(refusal(create("name", "\"" + std::string(32, 'n') + "\"")),
            "name: 1-31 bytes of UTF-8 without control characters");
  for (const char* field : {"name", "format", "game", "race", "entrants"}) {
    EXPECT_EQ(refusal(create(field, "")),
              std::string(field) + ": missing (tournament-create needs it)");
  }
  EXPECT_EQ(refusal(create("tournament", R"("t-1")")),
            "tournament: not a field of tournament-create");
  EXPECT_EQ(refusal(R"({"verb":"tournament-start"})"),
            "tournament: missing (tournament-start needs it)");
  EXPECT_EQ(refusal(R"({"verb":"tournament-cancel"})"),
            "tournament: missing (tournament-cancel needs it)");
  EXPECT_EQ(refusal(R"({"verb":"tournament-start","tournament":""})"),
            "tournament: 1-39 printable bytes");
  EXPECT_EQ(refusal(R"({"verb":"tournament-cancel","tournament":")" + std::string(40, 't') + "\"}"),
            "tournament: 1-39 printable bytes");
  EXPECT_EQ(refusal(R"({"verb":"tournament-start","tournament":"t\u001b1"})"),
            "tournament: 1-39 printable bytes");
  EXPECT_EQ(refusal(R"({"verb":"tournament-start","match":"t-1"})"),
            "match: not a field of tournament-start");
  EXPECT_EQ(refusal(R"({"verb":"tournaments","name":"Cup"})"), "name: not a field of tournaments");
}

TEST(AdminCommandLine, TournamentVerbsAreCheckedBeforeAnyServerIsAsked) {
  // No server listens on this socket: a command line that passes its checks fails to connect
  // (1); one that does not is refused first (2).
  const std::string socket = "/tmp/pool-admin-test-nobody-" + std::to_string(::getpid()) + ".sock";
  auto run = [&](std::vector<const char*> words) {
    std::vector<const char*> argv{"pool-server", "--socket", socket.c_str(), "admin"};
    argv.insert(argv.end(), words.begin(), words.end());
    return runAdminCommand(static_cast<int>(argv.size()), argv.data(), "/tmp/none.db");
  };
  EXPECT_EQ(run({"tournament-create", "Spring", "Open"}), 1);
  EXPECT_EQ(run({"tournament-create", "Spring", "--format", "round-robin", "--game", "22", "--race",
                 "15", "--entrants", "3"}),
            1);
  EXPECT_EQ(run({"tournament-create", "Cup", "--race", "5", "--handicap"}), 1);
  EXPECT_EQ(run({"tournaments", "--handicap"}), 2) << "a tournament-create flag";
  EXPECT_EQ(run({"tournament-start", "ab-t1"}), 1);
  EXPECT_EQ(run({"tournament-cancel", "ab-t1"}), 1);
  EXPECT_EQ(run({"tournaments"}), 1);
  EXPECT_EQ(run({"tournament-create"}), 2);
  EXPECT_EQ(run({"tournament-create", "Cup", "--format", "triple"}), 2);
  EXPECT_EQ(run({"tournament-create", "Cup", "--game", "7"}), 2);
  EXPECT_EQ(run({"tournament-create", "Cup", "--race", "0"}), 2);
  EXPECT_EQ(run({"tournament-create", "Cup", "--entrants", "33"}), 2);
  EXPECT_EQ(run({"tournament-start"}), 2);
  EXPECT_EQ(run({"tournament-cancel", "a", "b"}), 2);
  EXPECT_EQ(run({"tournaments", "extra"}), 2);
  EXPECT_EQ(run({"close", "t-1", "late", "--format", "double"}), 2);
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
