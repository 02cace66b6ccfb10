// A tournament's JSON: a round trip mid-tournament, and text that is not a tournament refused.
#include "server/tournament/tournament.h"
#include "tournament/field.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <functional>

namespace pool::tournament {
namespace {

using test::made;
using test::play;

/// A double elimination of six part played: reports, a forfeit, a match in play.
Tournament halfPlayed() {
  Tournament t = made(Format::DoubleElimination, 6, {.raceTo = 5});
  play(t, t.readyMatches().front(), t.matches()[t.readyMatches().front()].b);
  EXPECT_TRUE(t.forfeit(5));
  EXPECT_TRUE(t.start(t.readyMatches().front()));
  return t;
}

void expectSameTournament(const Tournament& x, const Tournament& y) {
  EXPECT_EQ(x.format(), y.format());
  EXPECT_EQ(x.options().raceTo, y.options().raceTo);
  ASSERT_EQ(x.entrants().size(), y.entrants().size());
  for (std::size_t e = 0; e < x.entrants().size(); ++e) {
    EXPECT_EQ(x.entrants()[e].id, y.entrants()[e].id);
    EXPECT_EQ(x.entrants()[e].name, y.entrants()[e].name);
    EXPECT_EQ(x.entrants()[e].rating, y.entrants()[e].rating);
    EXPECT_EQ(x.entrants()[e].bot, y.entrants()[e].bot);
    EXPECT_EQ(x.withdrawn(static_cast<int>(e)), y.withdrawn(static_cast<int>(e)));
  }
  ASSERT_EQ(x.matches().size(), y.matches().size());
  for (std::size_t i = 0; i < x.matches().size(); ++i) {
    const Match& a = x.matches()[i];
    const Match& b = y.matches()[i];
    EXPECT_EQ(a.round, b.round);
    EXPECT_EQ(a.a, b.a);
    EXPECT_EQ(a.b, b.b);
    EXPECT_EQ(a.state, b.state);
    EXPECT_EQ(a.winner, b.winner);
    EXPECT_EQ(a.racksA, b.racksA);
    EXPECT_EQ(a.racksB, b.racksB);
    EXPECT_EQ(a.forfeit, b.forfeit);
  }
  EXPECT_EQ(x.readyMatches(), y.readyMatches());
  EXPECT_EQ(x.finished(), y.finished());
  EXPECT_EQ(x.cancelled(), y.cancelled());
  EXPECT_EQ(x.champion(), y.champion());
  EXPECT_EQ(x.toJson(), y.toJson());
}

// Stored mid-tournament and restored (a server restart): the same tournament, which plays on to
// the same end as the original.
TEST(TournamentJson, RoundTripMidTournament) {
  Tournament original = halfPlayed();
  Result<Tournament> restored = Tournament::fromJson(original.toJson());
  ASSERT_TRUE(restored) << restored.error();
  expectSameTournament(original, *restored);
  for (Tournament* t : {&original, &restored.value()}) {
    for (const Match& m : t->matches()) {
      if (m.state == MatchState::InPlay) {
        ASSERT_TRUE(t->report(m.index, m.a, 5, 3));
      }
    }
    test::playByBetterSeed(*t);
    EXPECT_TRUE(t->finished());
  }
  expectSameTournament(original, *restored);
}

// Every format, names with quotes and non-ASCII letters, ratings that are not round, cancelled.
TEST(TournamentJson, RoundTripEveryFormatAndCancelled) {
  for (const Format format :
       {Format::SingleElimination, Format::DoubleElimination, Format::RoundRobin}) {
    std::vector<Entrant> entrants = test::field(7);
    entrants[2].name = "Zoë \"the rocket\" \\ O'Sullivan";
    entrants[3].rating = 1523.0 / 7.0;
    Result<Tournament> made7 = Tournament::create(format, entrants);
    ASSERT_TRUE(made7);
    Tournament& t = made7.value();
    play(t, t.readyMatches().front(), t.matches()[t.readyMatches().front()].a);
    ASSERT_TRUE(t.start(t.readyMatches().front()));
    ASSERT_TRUE(t.cancel());
    const Result<Tournament> back = Tournament::fromJson(t.toJson());
    ASSERT_TRUE(back) << back.error();
    expectSameTournament(t, *back);
  }
}

// Not a tournament: each refused with code bad_json and one line, none crashing.
TEST(TournamentJson, RefusesGarbage) {
  const std::string good = halfPlayed().toJson();
  const nlohmann::json doc = nlohmann::json::parse(good);
  const auto edited = [&](const std::function<void(nlohmann::json&)>& edit) {
    nlohmann::json copy = doc;
    edit(copy);
    return copy.dump();
  };
  const std::vector<std::string> bad = {
      "",
      "{",
      "null",
      "[]",
      "42",
      "\"text\"",
      good.substr(0, good.size() / 2),
      edited([](auto& j) { j.erase("log"); }),
      edited([](auto& j) { j["version"] = 2; }),
      edited([](auto& j) { j["version"] = 1.5; }),
      edited([](auto& j) { j["format"] = "swiss"; }),
      edited([](auto& j) { j["format"] = 3; }),
      edited([](auto& j) { j["options"]["raceTo"] = -3; }),
      edited([](auto& j) { j["options"]["raceTo"] = 1e30; }),
      edited([](auto& j) { j["options"] = "race to 5"; }),
      edited([](auto& j) { j["entrants"] = nlohmann::json::array(); }),
      edited([](auto& j) { j["entrants"][0]["id"] = j["entrants"][1]["id"]; }),
      edited([](auto& j) { j["entrants"][0]["rating"] = "high"; }),
      edited([](auto& j) { j["entrants"][0].erase("bot"); }),
      edited([](auto& j) { j["entrants"][0] = 7; }),
      edited([](auto& j) { j["log"][0]["call"] = "undo"; }),
      edited([](auto& j) { j["log"][0]["match"] = 999; }),
      edited([](auto& j) { j["log"][0]["match"] = 4294967296LL; }),
      edited([](auto& j) { j["log"][0]["match"] = -1; }),
      edited([](auto& j) { j["log"][1]["winner"] = 5; }),
      edited([](auto& j) { j["log"][1]["racks"] = {5}; }),
      edited([](auto& j) {
        j["log"][1]["racks"] = {2, 5, 1};
      }),
      edited([](auto& j) {
        j["log"][1]["racks"] = {"5", 2};
      }),
      edited([](auto& j) {
        j["log"].push_back({{"call", "forfeit"}, {"entrant", 5}});
      }),
      edited([](auto& j) { j["log"].push_back(j["log"][0]); }),
      edited([](auto& j) {
        j["log"] = {1, 2};
      }),
      edited([](auto& j) { j["matches"][0]["winner"] = 0; }),
      edited([](auto& j) { j["matches"].erase(0); }),
      edited([](auto& j) { j.erase("matches"); }),
  };
  for (const std::string& text : bad) {
    const Result<Tournament> t = Tournament::fromJson(text);
    EXPECT_FALSE(t) << text;
    EXPECT_EQ(t.code(), "bad_json") << text;
    EXPECT_EQ(t.error().find('\n'), std::string::npos) << t.error();
    EXPECT_EQ(t.error().rfind("tournament JSON: ", 0), 0u) << t.error();
  }
  EXPECT_TRUE(Tournament::fromJson(good));
}

// Bytes that are not UTF-8 inside a JSON string: refused, not thrown.
TEST(TournamentJson, RefusesBytesThatAreNotUtf8) {
  std::string text = halfPlayed().toJson();
  const std::size_t at = text.find("Player 1");
  ASSERT_NE(at, std::string::npos);
  text[at] = '\xff';
  const Result<Tournament> t = Tournament::fromJson(text);
  EXPECT_FALSE(t);
  EXPECT_EQ(t.code(), "bad_json");
}

}  // namespace
}  // namespace pool::tournament
