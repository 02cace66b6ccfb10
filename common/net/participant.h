// A DDS domain participant: the entry point to one DDS domain.
#pragma once

#include <cstdint>

#include "net/entity.h"

namespace pool::net {

/// The highest DDS domain id (DDS maps ids above it to no port).
inline constexpr std::uint32_t kMaxDomainId = 232;

/// Membership of one DDS domain. The configuration comes from CYCLONEDDS_URI in the environment
/// (Cyclone's defaults when unset: multicast discovery on the LAN); tests point it at
/// assets/cyclone-lo.xml. Deleting the participant deletes every entity created in it.
class Participant {
 public:
  /// Joins domain `domain` (0–232). Throws DdsError when the id is out of range or the
  /// configuration is unusable.
  explicit Participant(std::uint32_t domain);

  std::int32_t handle() const { return entity_.handle(); }
  std::uint32_t domain() const { return domain_; }

 private:
  Entity entity_;
  std::uint32_t domain_;
};

}  // namespace pool::net
