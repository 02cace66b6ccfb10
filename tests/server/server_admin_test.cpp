// The operator's commands on a live pool-server: list, close, ban, status counters, bad input,
// and an online backup taken mid-match that opens and that a server resumes the match from.
#include <gtest/gtest.h>
#include <pwd.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "core/hex.h"
#include "server/store/match_store.h"
#include "server_fixture.h"

namespace pool::server::test {
namespace {

using Json = nlohmann::json;

/// What one `pool-server admin|status` run printed and its exit code.
struct Ran {
  int code = -1;
  std::string out;  ///< stdout and stderr
};

/// A scratch folder, removed with everything in it. The fixture's server outlives the test's body,
/// so it may still be writing into the folder (its database's journal, its admin socket): a file
/// that appears while the folder is being removed leaves the folder behind, it does not end the
/// test program.
struct TempDir {
  std::string path;
  TempDir() {
    char name[] = "/tmp/pool-admin-test-XXXXXX";
    path = ::mkdtemp(name);
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path, ignored);
  }
};

class ServerAdmin : public ServerTest {
 protected:
  /// Runs `pool-server WORDS` (each word single-quoted) and collects its output.
  static Ran run(const std::vector<std::string>& words) {
    std::string command = std::string(POOL_BIN_DIR) + "/pool-server";
    for (const auto& w : words) command += " '" + w + "'";
    command += " 2>&1";
    Ran ran;
    FILE* pipe = ::popen(command.c_str(), "r");
    if (!pipe) return ran;
    std::array<char, 4096> buffer{};
    while (std::size_t n = std::fread(buffer.data(), 1, buffer.size(), pipe)) {
      ran.out.append(buffer.data(), n);
    }
    const int status = ::pclose(pipe);
    ran.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return ran;
  }

  /// `pool-server admin --db DB --json ARGS`: the reply, which must be ok.
  Json admin(const std::string& db, std::vector<std::string> args) {
    args.insert(args.begin(), {"admin", "--db", db, "--json"});
    const Ran ran = run(args);
    EXPECT_EQ(ran.code, 0) << ran.out;
    const Json reply = Json::parse(ran.out, nullptr, false);
    EXPECT_TRUE(reply.is_object() && reply.value("ok", false)) << ran.out;
    return reply;
  }

  Json status(const std::string& db) { return admin(db, {"status"}); }

  /// Waits (bounded) until the status satisfies `ok`; returns the last status read.
  Json waitStatus(const std::string& db, const std::function<bool(const Json&)>& ok) {
    const auto deadline = std::chrono::steady_clock::now() + 15s;
    Json s = status(db);
    while (!ok(s) && std::chrono::steady_clock::now() < deadline) {
      std::this_thread::sleep_for(50ms);
      s = status(db);
    }
    return s;
  }
};

/// The match `id` of a `list` reply, or null.
const Json* listed(const Json& list, const std::string& id) {
  for (const auto& m : list["matches"]) {
    if (m["id"] == id) return &m;
  }
  return nullptr;
}

TEST_F(ServerAdmin, OperatorListsClosesBansAndReadsCountersOnALiveServer) {
  TempDir dir;
  const std::string db = dir.path + "/pool.db";
  start(kAdmin, {"--tables", "2", "--fast", "--db", db});
  TestClient a(kAdmin, "a"), b(kAdmin, "b"), c(kAdmin, "c"), d(kAdmin, "d");
  ASSERT_TRUE(a.waitForServer(2));
  const Seated one = seat(a, b, "t-1");
  const Seated two = seat(c, d, "t-2");

  // The socket is the server user's alone.
  struct stat st {};
  ASSERT_EQ(::stat((db + ".sock").c_str(), &st), 0);
  EXPECT_TRUE(S_ISSOCK(st.st_mode));
  EXPECT_EQ(st.st_mode & 0777, 0600u);

  // list: both matches with their players and keys.
  const Json list = admin(db, {"list"});
  const Json* first = listed(list, "t-1");
  ASSERT_TRUE(first) << list.dump();
  ASSERT_EQ((*first)["players"].size(), 2u);
  EXPECT_EQ((*first)["players"][0]["player"], "Ada");
  EXPECT_EQ((*first)["players"][1]["player"], "Bob");
  EXPECT_EQ((*first)["players"][1]["key"], hexOf(b.key().publicKey()));
  ASSERT_TRUE(listed(list, "t-2"));

  const Json before = status(db);
  EXPECT_EQ(before["health"], "ok");
  EXPECT_EQ(before["matches"], 4);  // two played, two kept free (--tables 2)
  EXPECT_EQ(before["players"], 4);
  EXPECT_EQ(before["joins_accepted"], 4);
  EXPECT_EQ(before["commands_accepted"], 0);

  // An accepted shot is counted, and so is its commit.
  a.send(breakShot(one, 0, 1));
  ASSERT_TRUE(a.waitFinal("t-1", 0, 1));
  Json after = waitStatus(db, [](const Json& s) { return s["commands_accepted"] == 1; });
  EXPECT_EQ(after["commands_accepted"], 1);
  EXPECT_GT(after["commits"].get<int>(), before["commits"].get<int>());
  EXPECT_GT(after["commit_ms_max"].get<double>(), 0.0);

  // close: the players of t-2 read why in its last state, then it is gone.
  admin(db, {"close", "t-2", "table", "needs", "new", "cloth"});
  const auto* closed =
      c.waitState("t-2", [](const pool_MatchState& s) { return s.phase == pool_PHASE_CLOSED; });
  ASSERT_TRUE(closed);
  EXPECT_STREQ(closed->last_verdict, "closed by the operator: table needs new cloth");
  EXPECT_TRUE(d.waitUntil(
      [&] { return std::count(d.disposed_infos.begin(), d.disposed_infos.end(), "t-2") > 0; },
      30s));
  EXPECT_FALSE(listed(admin(db, {"list"}), "t-2"));
  const std::size_t mark = c.mark();
  c.send(breakShot(two, 0, 1));
  const auto* gone = c.waitAnswer("t-2", 0, 1, mark);
  ASSERT_TRUE(gone);
  EXPECT_EQ(gone->reject_reason, pool_REJECT_NO_SUCH_MATCH);

  // ban: the key of whoever is to shoot in t-1; that seat's command is refused with the reason.
  const auto* state = a.waitState(
      "t-1", [](const pool_MatchState& s) { return s.shot_number == 1 && s.shooter >= 0; });
  ASSERT_TRUE(state);
  const int shooter = state->shooter;
  TestClient& banned = shooter == 0 ? a : b;
  const std::string key = hexOf(banned.key().publicKey());
  const Json ban = admin(db, {"ban", key, "abusive", "names"});
  EXPECT_EQ(ban["banned"], key);
  const std::uint32_t seq = banned.seq() + 1;
  const std::size_t from = banned.mark();
  banned.send(anyLegalShot(*state, one, seq));
  const auto* refused = banned.waitAnswer("t-1", shooter, seq, from);
  ASSERT_TRUE(refused);
  EXPECT_FALSE(refused->accepted);
  EXPECT_EQ(refused->reject_reason, pool_REJECT_MATCH_OVER);
  EXPECT_NE(std::string(refused->reject_text).find("banned from the server: abusive names"),
            std::string::npos)
      << refused->reject_text;
  // Nor may that key take a seat anywhere.
  const auto seat_again = banned.join(pool_JOIN_SEAT, "new", "Eve");
  ASSERT_TRUE(seat_again);
  EXPECT_EQ(seat_again->outcome, pool_JOIN_NOT_ALLOWED);
  EXPECT_NE(std::string(seat_again->reason).find("banned"), std::string::npos);
  after = waitStatus(db, [](const Json& s) { return s["commands_refused"] == 2; });
  EXPECT_EQ(after["commands_refused"], 2);  // the closed match's command and the banned one
  EXPECT_EQ(after["commands_accepted"], 1);
  EXPECT_EQ(after["joins_refused"], 1);
  EXPECT_EQ(after["matches"].get<int>(), 3);  // t-1 and the two free tables
  const Json bans = admin(db, {"bans"});
  ASSERT_EQ(bans["bans"].size(), 1u);
  EXPECT_EQ(bans["bans"][0]["key"], key);

  // Bad input: a clear error, nothing changed.
  const Json list_before = admin(db, {"list"});
  const int refused_before = status(db)["admin_refused"].get<int>();
  Ran bad = run({"admin", "--db", db, "ban", "xyz", "reason"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.out.find("key: an Ed25519 public key is 64 hex digits"), std::string::npos);
  bad = run({"admin", "--db", db, "close", "t-99", "no", "such"});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.out.find("no open match t-99"), std::string::npos) << bad.out;
  bad = run({"admin", "--db", db, "backup", db});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.out.find("a file is there already (not overwritten)"), std::string::npos);
  bad = run({"admin", "--db", db, "unban", std::string(64, 'a')});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.out.find("is not banned"), std::string::npos);
  bad = run({"admin", "--db", db, "explode"});
  EXPECT_EQ(bad.code, 2);
  EXPECT_NE(bad.out.find("'explode' is not one of"), std::string::npos);
  bad = run({"admin", "--db", dir.path + "/nothing.db", "list"});
  EXPECT_EQ(bad.code, 1);
  EXPECT_NE(bad.out.find("is pool-server running with this database?"), std::string::npos);
  // Raw requests the command line would not send: answered with an error each.
  for (const std::string& raw : std::vector<std::string>{
           "not json", R"({"verb":"close","match":"t-1"})", R"({"verb":"list","extra":1})",
           R"({"verb":"close","match":"t-1","reason":"a\u0007b"})", std::string(9000, 'x')}) {
    const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
    sockaddr_un address{};
    address.sun_family = AF_UNIX;
    std::strcpy(address.sun_path, (db + ".sock").c_str());
    ASSERT_EQ(::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    const std::string line = raw + "\n";
    ASSERT_EQ(::send(s, line.data(), line.size(), MSG_NOSIGNAL), static_cast<ssize_t>(line.size()));
    std::string reply;
    char buffer[512];
    for (ssize_t n; (n = ::recv(s, buffer, sizeof buffer, 0)) > 0;) reply.append(buffer, n);
    ::close(s);
    EXPECT_NE(reply.find(R"("ok":false)"), std::string::npos) << raw.substr(0, 40) << ": " << reply;
  }
  EXPECT_EQ(admin(db, {"list"})["matches"], list_before["matches"]);
  // Refused by the server: 3 from the command line, 4 raw (the too-long line is refused by the
  // socket itself and never reaches it).
  EXPECT_EQ(status(db)["admin_refused"].get<int>(), refused_before + 3 + 4);

  // Another user may not even connect (root runs the suite in CI; elsewhere this part is moot).
  if (::geteuid() == 0) {
    const passwd* nobody = ::getpwnam("nobody");
    ASSERT_TRUE(nobody);
    const pid_t child = ::fork();
    if (child == 0) {
      if (::setuid(nobody->pw_uid) != 0) ::_exit(3);
      const int s = ::socket(AF_UNIX, SOCK_STREAM, 0);
      sockaddr_un address{};
      address.sun_family = AF_UNIX;
      std::strcpy(address.sun_path, (db + ".sock").c_str());
      const int rc = ::connect(s, reinterpret_cast<sockaddr*>(&address), sizeof address);
      ::_exit(rc == 0 ? 1 : 0);
    }
    int wstatus = 0;
    ::waitpid(child, &wstatus, 0);
    EXPECT_TRUE(WIFEXITED(wstatus) && WEXITSTATUS(wstatus) == 0) << "nobody connected";
  }

  // The ban is in the database: a server started again on it still refuses that key.
  server_->signal(SIGTERM);
  ASSERT_EQ(server_->waitExit(10s), 0);
  start(kAdmin, {"--tables", "2", "--fast", "--db", db});
  // A new participant, so that it waits for the new server (the player keeps its key).
  TestClient player(kAdmin, "player");
  player.useKey(banned.key());
  player.setSeq(banned.seq());
  ASSERT_TRUE(player.waitForServer(3));
  EXPECT_EQ(admin(db, {"bans"})["bans"].size(), 1u);
  const auto rejoin = player.join(pool_JOIN_REJOIN, "t-1", "", -1, one.token[shooter]);
  ASSERT_TRUE(rejoin);
  EXPECT_EQ(rejoin->outcome, pool_JOIN_NOT_ALLOWED);
  EXPECT_NE(std::string(rejoin->reason).find("banned from the server: abusive names"),
            std::string::npos);
  // Lifted, the same key rejoins.
  admin(db, {"unban", key});
  const auto back = player.join(pool_JOIN_REJOIN, "t-1", "", -1, one.token[shooter]);
  ASSERT_TRUE(back);
  EXPECT_EQ(back->outcome, pool_JOIN_ACCEPTED) << back->reason;
  // `status` without --json prints the counters one per line.
  const Ran printed = run({"status", "--db", db});
  EXPECT_EQ(printed.code, 0);
  EXPECT_NE(printed.out.find("health: ok\n"), std::string::npos) << printed.out;
  EXPECT_NE(printed.out.find("commands_accepted: 0\n"), std::string::npos) << printed.out;
}

TEST_F(ServerAdmin, ABackupTakenMidMatchOpensAndAServerResumesTheMatchFromIt) {
  TempDir dir;
  const std::string db = dir.path + "/pool.db";
  const std::string copy = dir.path + "/copy.db";
  start(kAdminBackup, {"--tables", "1", "--fast", "--db", db});
  TestClient a(kAdminBackup, "a"), b(kAdminBackup, "b");
  ASSERT_TRUE(a.waitForServer(1));
  const Seated one = seat(a, b, "t-1");
  a.send(breakShot(one, 0, 1));
  ASSERT_TRUE(a.waitFinal("t-1", 0, 1));
  const auto* state = a.waitState(
      "t-1", [](const pool_MatchState& s) { return s.shot_number == 1 && s.shooter >= 0; });
  ASSERT_TRUE(state);
  const pool_MatchState at_backup = *state;

  // The server holds its file exclusively: only it can copy it.
  const Json reply = admin(db, {"backup", copy});
  EXPECT_EQ(reply["backup"], copy);
  EXPECT_GT(reply["bytes"].get<int>(), 0);
  std::cout << "backup of " << reply["bytes"] << " bytes (" << reply["pages"] << " pages) took "
            << reply["ms"] << " ms inside the server's loop\n";
  EXPECT_FALSE(std::filesystem::exists(copy + ".partial"));

  // The copy opens as a pool database and holds the match as it stood.
  {
    auto opened = store::MatchStore::open(copy);
    ASSERT_TRUE(opened) << opened.error();
    const auto match = (*opened)->match("t-1");
    ASSERT_TRUE(match);
    EXPECT_EQ(match->shot_number, 1u);
    EXPECT_EQ(match->seats[0].player, "Ada");
    EXPECT_EQ((*opened)->shots("t-1").size(), 1u);
  }

  // The original server goes away; one started on the copy resumes the match.
  server_->signal(SIGKILL);
  server_->waitExit(10s);
  start(kAdminBackup, {"--tables", "0", "--fast", "--db", copy});
  // The players come back as new participants with their keys (and wait for the new server).
  TestClient a2(kAdminBackup, "a2"), b2(kAdminBackup, "b2");
  a2.useKey(a.key());
  a2.setSeq(a.seq());
  b2.useKey(b.key());
  b2.setSeq(b.seq());
  ASSERT_TRUE(a2.waitForServer(1));
  ASSERT_TRUE(b2.waitForServer(1));
  const int shooter = at_backup.shooter;
  TestClient& next = shooter == 0 ? a2 : b2;
  const auto rejoined_a = a2.join(pool_JOIN_REJOIN, "t-1", "", -1, one.token[0]);
  const auto rejoined_b = b2.join(pool_JOIN_REJOIN, "t-1", "", -1, one.token[1]);
  ASSERT_TRUE(rejoined_a && rejoined_b);
  EXPECT_EQ(rejoined_a->outcome, pool_JOIN_ACCEPTED) << rejoined_a->reason;
  EXPECT_EQ(rejoined_b->outcome, pool_JOIN_ACCEPTED) << rejoined_b->reason;
  const auto* resumed = next.waitState("t-1", [&](const pool_MatchState& s) {
    return s.shot_number == 1 && s.seats[0].connected && s.seats[1].connected;
  });
  ASSERT_TRUE(resumed);
  EXPECT_EQ(resumed->shooter, at_backup.shooter);
  ASSERT_EQ(resumed->balls._length, at_backup.balls._length);
  for (std::uint32_t i = 0; i < resumed->balls._length; ++i) {
    EXPECT_EQ(resumed->balls._buffer[i].pos.x, at_backup.balls._buffer[i].pos.x);
    EXPECT_EQ(resumed->balls._buffer[i].pos.y, at_backup.balls._buffer[i].pos.y);
  }
  const std::uint32_t seq = std::max(next.seq(), resumed->seat_seq[shooter]) + 1;
  next.send(anyLegalShot(*resumed, one, seq));
  const auto* shot = next.waitFinal("t-1", shooter, seq);
  ASSERT_TRUE(shot) << "the resumed match took no shot";
  EXPECT_EQ(shot->shot_number, 2u);
  // The server on the copy stops before the folder holding it goes.
  server_->signal(SIGTERM);
  server_->waitExit(10s);
}

}  // namespace
}  // namespace pool::server::test
