// The partitions a test observer or adversary uses to see (or reach) every match at once.
#pragma once

#include <string>
#include <vector>

#include "net/match_partition.h"

namespace pool::test {

/// The default partition (lobby, joins) and every match's own, by a wildcard: what an observer
/// recording a whole domain subscribes to, and what an adversary publishes into.
inline std::vector<std::string> everyPartition() {
  return {"", std::string(net::kMatchPartitionPrefix) + "*"};
}

}  // namespace pool::test
