// The gateway's fan-out with browsers faked as sinks: late join, one message shared by every
// browser of a match, bad requests refused without a change, slow browsers dropped alone, table
// names from the wire kept inside assets/tables, a snooker table's marks and balls.
#include "client/web/gateway.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "client/web/out_queue.h"
#include "client/web/web_json.h"
#include "support/client_fixture.h"
#include "table/table_spec.h"

namespace pool::web {
namespace {

using client::test::ClientIntegrationTest;
using nlohmann::json;

/// A browser that keeps what it was sent (up to `room` messages; then it says it is full).
struct FakeBrowser {
  std::vector<Message> got;
  std::size_t room = 1000;

  Gateway::Sink sink() {
    return [this](const Message& m) {
      if (got.size() >= room) return false;
      got.push_back(m);
      return true;
    };
  }
  std::vector<std::string> types() const {
    std::vector<std::string> out;
    for (const auto& m : got) out.push_back(json::parse(*m).value("type", ""));
    return out;
  }
  json last() const { return json::parse(*got.back()); }
};

client::LobbyEntry entry(const std::string& match, const std::string& table = "wpa-9ft") {
  client::LobbyEntry e;
  e.match = match;
  e.server = "srv";
  e.table = table;
  e.phase = protocol::MatchPhase::Open;
  e.players = {"alice", "bob"};
  e.seats_taken = 2;
  return e;
}

client::MatchView state(const std::string& match, std::uint32_t revision) {
  client::MatchView v;
  v.match = match;
  v.revision = revision;
  v.phase = protocol::MatchPhase::Open;
  v.seats[0].name = "alice";
  v.seats[1].name = "bob";
  v.shooter = 1;
  v.balls.push_back(physics::restingBall(0, {-0.6, 0.1}, 0.028575));
  return v;
}

client::TableFrame frame(const std::string& match, std::uint32_t k) {
  client::TableFrame f;
  f.match = match;
  f.frame = k;
  f.sim_time = k / 60.0;
  f.shot_number = 1;
  f.balls.push_back(physics::restingBall(0, {-0.6 + 0.01 * k, 0.1}, 0.028575));
  return f;
}

class GatewayTest : public ClientIntegrationTest {
 protected:
  void SetUp() override {
    ClientIntegrationTest::SetUp();
    open(client::test::kWebGateway, "web-gateway");
    client_ = std::make_unique<client::GameClient>(
        client::ClientOptions{client::test::kWebGateway, "", "web", {}, [](auto&&...) {}});
    gateway_ = std::make_unique<Gateway>(*client_);
  }
  std::unique_ptr<client::GameClient> client_;
  std::unique_ptr<Gateway> gateway_;
};

TEST_F(GatewayTest, ALateBrowserGetsTheTableTheLatestStateAndResultThenTheMatchOnly) {
  FakeBrowser early, late, elsewhere;
  gateway_->attach(1, early.sink());
  ASSERT_EQ(early.types(), std::vector<std::string>{"lobby"});
  gateway_->handle(entry("srv-1"));
  gateway_->handle(entry("srv-2"));
  gateway_->step(0.0);  // the lobby changed: every browser hears it
  EXPECT_EQ(early.last()["matches"].size(), 2u);

  EXPECT_EQ(gateway_->watch(1, "srv-1"), "");
  gateway_->handle(state("srv-1", 5));
  client::ShotReport report;
  report.match = "srv-1";
  report.accepted = true;
  report.shot_number = 1;
  report.verdict_text = "legal; open, seat 1 to shoot";
  gateway_->handle(report);
  gateway_->handle(state("srv-2", 9));  // another match: not for this browser

  gateway_->attach(2, late.sink());
  gateway_->attach(3, elsewhere.sink());
  ASSERT_EQ(gateway_->watch(2, "srv-1"), "");
  ASSERT_EQ(gateway_->watch(3, "srv-2"), "");
  EXPECT_EQ(late.types(),
            (std::vector<std::string>{"lobby", "watching", "table", "state", "result"}));
  const json table = json::parse(*late.got[2]);
  EXPECT_EQ(table["name"], "wpa-9ft");
  EXPECT_EQ(table["holes"].size(), 6u);
  EXPECT_EQ(table["colours"]["balls"].size(), 16u);
  EXPECT_EQ(json::parse(*late.got[3])["state"]["revision"], 5);
  EXPECT_EQ(json::parse(*elsewhere.got[3])["state"]["revision"], 9);

  // One frame: the same bytes for both watchers of srv-1, nothing for srv-2's.
  const std::size_t before = elsewhere.got.size();
  gateway_->handle(frame("srv-1", 3));
  ASSERT_EQ(early.types().back(), "frame");
  ASSERT_EQ(late.types().back(), "frame");
  EXPECT_EQ(early.got.back().get(), late.got.back().get()) << "one message shared, not copied";
  EXPECT_EQ(elsewhere.got.size(), before);
  const json f = late.last();
  EXPECT_EQ(f["shot"], 1);
  EXPECT_NEAR(f["balls"][0][1].get<double>(), -0.57, 1e-9);
}

TEST_F(GatewayTest, BadRequestsAreRefusedAndChangeNothing) {
  FakeBrowser b;
  gateway_->attach(1, b.sink());
  gateway_->handle(entry("srv-1"));
  ASSERT_EQ(gateway_->watch(1, "srv-1"), "");
  const std::size_t got = b.got.size();
  EXPECT_NE(gateway_->watch(1, "srv-404"), "");
  EXPECT_EQ(b.last()["type"], "error");
  EXPECT_EQ(b.got.size(), got + 1);
  EXPECT_EQ(gateway_->watchers("srv-1"), 1u) << "a refused watch keeps the match watched";

  std::string error;
  for (const char* bad :
       {"", "[]", "{\"watch\":3}", "{\"watch\":\"a b\"}", "{\"seat\":\"srv-1\"}",
        "{\"watch\":\"srv-1\",\"shoot\":1}", "not json", "{\"replay\":{\"match\":\"srv-1\"}}",
        "{\"replay\":{\"match\":\"srv-1\",\"shot\":0}}",
        "{\"replay\":{\"match\":\"srv-1\",\"shot\":-2}}",
        "{\"replay\":{\"match\":\"srv-1\",\"shot\":1.5}}",
        "{\"replay\":{\"match\":\"\",\"shot\":1}}",
        "{\"replay\":{\"match\":\"srv-1\",\"shot\":4294967296}}",
        "{\"replay\":{\"match\":\"srv-1\",\"shot\":1,\"x\":1}}"}) {
    error.clear();
    EXPECT_FALSE(parseRequest(bad, error)) << bad;
    EXPECT_FALSE(error.empty()) << bad;
    EXPECT_EQ(error.find('\n'), std::string::npos) << bad;
  }
  EXPECT_FALSE(parseRequest("{\"watch\":\"" + std::string(65, 'x') + "\"}", error));
  auto watched = [&](const std::string& text) {
    const auto request = parseRequest(text, error);
    const auto* watch = request ? std::get_if<WatchRequest>(&*request) : nullptr;
    return watch ? watch->match : std::string("?");
  };
  EXPECT_EQ(watched("{\"watch\":\"srv-1\"}"), "srv-1");
  EXPECT_EQ(watched("{\"watch\":\"\"}"), "");
  const auto replay = parseRequest("{\"replay\":{\"match\":\"srv-1\",\"shot\":12}}", error);
  ASSERT_TRUE(replay && std::holds_alternative<ReplayRequest>(*replay)) << error;
  EXPECT_EQ(std::get<ReplayRequest>(*replay).match, "srv-1");
  EXPECT_EQ(std::get<ReplayRequest>(*replay).shot, 12u);
}

TEST_F(GatewayTest, ATableNameFromTheWireNeverLeavesAssetsTables) {
  for (const char* bad : {"../../etc/passwd", "/etc/passwd", "wpa-9ft.json", "WPA", "",
                          "a-very-long-table-name-that-goes-on-and-on"}) {
    EXPECT_FALSE(validTableName(bad)) << bad;
    EXPECT_FALSE(tableJson(bad)) << bad;
  }
  EXPECT_FALSE(tableJson("no-such-table"));
  ASSERT_TRUE(tableJson("wpa-7ft"));

  FakeBrowser b;
  gateway_->attach(1, b.sink());
  gateway_->handle(entry("srv-1", "../../../etc/passwd"));
  ASSERT_EQ(gateway_->watch(1, "srv-1"), "");
  const json said = json::parse(*b.got[2]);
  EXPECT_EQ(said["type"], "error");
  EXPECT_NE(said["text"].get<std::string>().find("cannot draw table"), std::string::npos);
}

TEST_F(GatewayTest, ASlowBrowserIsDroppedAndTheOthersGetEverything) {
  FakeBrowser slow, fast;
  gateway_->attach(1, slow.sink());
  gateway_->attach(2, fast.sink());
  gateway_->handle(entry("srv-1"));
  ASSERT_EQ(gateway_->watch(1, "srv-1"), "");
  ASSERT_EQ(gateway_->watch(2, "srv-1"), "");
  slow.room = slow.got.size() + 5;
  for (std::uint32_t k = 1; k <= 50; ++k) gateway_->handle(frame("srv-1", k));
  EXPECT_EQ(gateway_->browsers(), 1u);
  EXPECT_EQ(gateway_->watchers("srv-1"), 1u);
  int frames = 0;
  for (const auto& t : fast.types()) frames += t == "frame" ? 1 : 0;
  EXPECT_EQ(frames, 50);
  EXPECT_EQ(slow.got.size(), slow.room);
}

// A snooker table's message: the marks from its spec's figures (the baulk line 737 mm from the
// bottom cushion at -x, the D's radius, the black's spot 324 mm from the top cushion), 22 balls
// without numbers or stripes, the fifteen reds alike and the six colours apart from the reds and
// from one another; a pool table's carries no marks and its 16 balls.
TEST(TableJsonTest, ASnookerTableCarriesItsMarksAndItsSetOfBalls) {
  const auto spec = table::loadTableSpec("snooker-12ft");
  ASSERT_TRUE(spec) << spec.error();
  ASSERT_TRUE(spec->snooker_marks.has_value());
  const auto text = tableJson("snooker-12ft");
  ASSERT_TRUE(text) << text.error();
  const json table = json::parse(*text);
  const json& marks = table.at("snooker_marks");
  ASSERT_TRUE(marks.is_object());
  EXPECT_NEAR(marks.at("baulk_x").get<double>(),
              -spec->length / 2 + spec->snooker_marks->baulk_line, 1e-12);
  EXPECT_NEAR(marks.at("d_radius").get<double>(), spec->snooker_marks->d_radius, 1e-12);
  EXPECT_NEAR(marks.at("spots").at("black")[0].get<double>(),
              spec->length / 2 - spec->snooker_marks->black_spot, 1e-12);
  EXPECT_NEAR(marks.at("spots").at("pink")[0].get<double>(), spec->length / 4, 1e-12);
  EXPECT_GT(marks.at("line_width").get<double>(), 0.0015);
  EXPECT_LT(marks.at("line_width").get<double>(), 0.0035);
  EXPECT_EQ(table.at("colours").at("chalk").size(), 3u);

  const json& balls = table.at("colours").at("balls");
  ASSERT_EQ(balls.size(), 22u) << "the cue ball, 15 reds and six colours: ids 0-21";
  for (const json& ball : balls) {
    EXPECT_EQ(ball.at("number"), 0);
    EXPECT_FALSE(ball.at("striped").get<bool>());
  }
  const auto colour = [&](int id) { return balls[static_cast<std::size_t>(id)].at("colour"); };
  for (int id = 2; id <= 15; ++id) EXPECT_EQ(colour(id), colour(1)) << id;
  for (int id = 16; id <= 21; ++id) {
    EXPECT_NE(colour(id), colour(1)) << id;
    EXPECT_NE(colour(id), colour(0)) << id;
    for (int other = 16; other < id; ++other) EXPECT_NE(colour(id), colour(other)) << id;
  }

  const auto pool = tableJson("wpa-9ft");
  ASSERT_TRUE(pool) << pool.error();
  const json pool_table = json::parse(*pool);
  EXPECT_TRUE(pool_table.at("snooker_marks").is_null());
  EXPECT_EQ(pool_table.at("colours").at("balls").size(), 16u);
}

TEST(OutQueueTest, HoldsMessagesUpToItsBudgetAndRefusesPastIt) {
  OutQueue queue(100);
  const auto msg = [](std::size_t n) { return std::make_shared<const std::string>(n, 'x'); };
  EXPECT_TRUE(queue.push(msg(60)));
  EXPECT_TRUE(queue.push(msg(40)));
  EXPECT_FALSE(queue.push(msg(1)));
  EXPECT_EQ(queue.size(), 2u);
  EXPECT_EQ(queue.bytes(), 100u);
  queue.pop();
  EXPECT_TRUE(queue.push(msg(50)));
  EXPECT_EQ(queue.bytes(), 90u);
  EXPECT_EQ(queue.front()->size(), 40u);
}

}  // namespace
}  // namespace pool::web
