// DDS publishers and subscribers bound to named partitions: the scope that a writer or reader
// created under them publishes or subscribes in.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "net/entity.h"
#include "net/participant.h"

namespace pool::net {

/// A publisher whose writers publish in `partitions` (net/match_partition.h names a match's).
/// Throws DdsError when DDS refuses it.
class Publisher {
 public:
  Publisher(const Participant& participant, const std::vector<std::string>& partitions);
  std::int32_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

/// A subscriber whose readers receive what is published in `partitions`. Throws DdsError when
/// DDS refuses it.
class Subscriber {
 public:
  Subscriber(const Participant& participant, const std::vector<std::string>& partitions);
  std::int32_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

}  // namespace pool::net
