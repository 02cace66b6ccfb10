// Presence: a client is there while the writer of its requests is matched; a seated client stays
// tied to its seat request's writer; one writer keeps a bounded number of clients.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>

#include "server/presence.h"

namespace pool::server::test {
namespace {

std::set<std::string> ids(const std::vector<Presence::Gone>& gone) {
  std::set<std::string> out;
  for (const auto& g : gone) out.insert(g.client);
  return out;
}

TEST(Presence, AClientGoesWithItsWriterAndNotBefore) {
  Presence p;
  EXPECT_TRUE(p.answered("ada", 7, "participant A", false).empty());
  EXPECT_TRUE(p.answered("bob", 9, "participant B", false).empty());
  EXPECT_TRUE(p.fresh());
  EXPECT_TRUE(p.sweep({7, 9}).empty()) << "both writers matched";
  EXPECT_FALSE(p.fresh());
  const auto gone = p.sweep({9});
  ASSERT_EQ(gone.size(), 1u);
  EXPECT_EQ(gone[0].client, "ada");
  EXPECT_EQ(gone[0].sender, "participant A");
  EXPECT_FALSE(p.present("ada"));
  EXPECT_TRUE(p.present("bob"));
  EXPECT_TRUE(p.sweep({9}).empty()) << "gone once";
}

TEST(Presence, AStrangerWritingUnderASeatedClientsIdNeitherMovesNorEndsHerPresence) {
  Presence p;
  p.answered("ada", 7, "participant A", true);  // her accepted, signed seat request
  // The stranger's spectate requests under her id, answered from his own writer.
  p.answered("ada", 66, "participant S", false);
  EXPECT_TRUE(p.sweep({7}).empty()) << "the stranger's writer went: she is still there";
  EXPECT_TRUE(p.present("ada"));
  EXPECT_EQ(ids(p.sweep({})), std::set<std::string>{"ada"}) << "her own writer went";
}

TEST(Presence, ASeatRequestFromANewWriterMovesTheSeatedClientThere) {
  Presence p;
  p.answered("ada", 7, "participant A", true);
  p.answered("ada", 8, "participant A2", true);  // her rejoin after a restart of her process
  EXPECT_TRUE(p.sweep({8}).empty()) << "her old writer's going is not hers any more";
  EXPECT_EQ(ids(p.sweep({})), std::set<std::string>{"ada"});
}

TEST(Presence, AnUntiedClientFollowsItsLatestWriter) {
  Presence p;
  p.answered("ada", 7, "participant A", true);
  p.untieUnless([](const std::string&) { return false; });  // her seat was freed
  p.answered("ada", 8, "participant A", false);
  EXPECT_TRUE(p.sweep({8}).empty());
  EXPECT_TRUE(p.present("ada"));
}

TEST(Presence, OneWriterKeepsABoundedNumberOfClientsAndItsSeatedOnes) {
  Presence p;
  p.answered("ada", 7, "participant A", true);
  std::set<std::string> let_go;
  // A flood of 10 000 invented client ids from the same writer.
  for (int i = 0; i < 10'000; ++i) {
    for (const auto& g : p.answered("ghost-" + std::to_string(i), 7, "participant A", false)) {
      let_go.insert(g.client);
    }
  }
  EXPECT_EQ(p.size(), Presence::kClientsPerWriter);
  EXPECT_EQ(let_go.size(), 10'000u - (Presence::kClientsPerWriter - 1));
  EXPECT_TRUE(p.present("ada")) << "a seated client is never let go for room";
  EXPECT_TRUE(p.present("ghost-9999"));
  EXPECT_FALSE(p.present("ghost-0")) << "the oldest go first";
  EXPECT_EQ(let_go.count("ada"), 0u);
  // A client moving between two writers again and again costs no more than itself.
  for (int i = 0; i < 10'000; ++i)
    p.answered("hopper", 20 + static_cast<std::uint64_t>(i % 2), "x", false);
  EXPECT_TRUE(p.present("hopper"));
  EXPECT_EQ(ids(p.sweep({7})), std::set<std::string>{"hopper"});
  EXPECT_EQ(p.size(), Presence::kClientsPerWriter);
}

}  // namespace
}  // namespace pool::server::test
