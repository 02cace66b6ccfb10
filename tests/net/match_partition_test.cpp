// Partition names from match ids: a server's ids make one each, and nothing that DDS could read
// as a pattern (or that is not a plain id) ever becomes a partition name.
#include "net/match_partition.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace pool::net {
namespace {

TEST(MatchPartition, AServersMatchIdsNameTheirPartition) {
  EXPECT_EQ(*matchPartition("srv-1"), "pool.match.srv-1");
  EXPECT_EQ(*matchPartition("lan.hall_2-1234"), "pool.match.lan.hall_2-1234");
  // The longest id a server makes: a 24-character server id, '-', up to 14 digits.
  const std::string longest = std::string(24, 'a') + "-" + std::string(14, '9');
  EXPECT_EQ(*matchPartition(longest), std::string(kMatchPartitionPrefix) + longest);
  // Different ids, different partitions.
  EXPECT_NE(*matchPartition("srv-1"), *matchPartition("srv-10"));
}

TEST(MatchPartition, WildcardsAndOtherCharactersNameNoPartition) {
  const std::vector<std::string> ids{"",
                                     "*",
                                     "srv-*",
                                     "srv-?",
                                     "srv-[1]",
                                     "a b",
                                     "a,b",
                                     "srv/1",
                                     "srv\\1",
                                     "zo\xc3\xab-1",
                                     std::string("srv\0-1", 6),
                                     "srv-1\n",
                                     std::string(40, 'a')};
  for (const std::string& bad : ids) {
    const auto partition = matchPartition(bad);
    EXPECT_FALSE(partition) << "'" << bad << "' made " << (partition ? *partition : "");
    if (!partition) {
      EXPECT_FALSE(partition.error().empty());
    }
  }
}

}  // namespace
}  // namespace pool::net
