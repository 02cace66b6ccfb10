// A typed DDS topic of one wire type.
#pragma once

#include <string_view>

#include "net/dds_detail.h"
#include "net/entity.h"
#include "net/messages.h"
#include "net/participant.h"

namespace pool::net {

/// The topic carrying wire type T in `participant`. Throws DdsError when DDS refuses it (e.g. the
/// name is taken by another type).
template <class T>
class Topic {
 public:
  /// The topic under its protocol name (topics.h), or under `name` (tests, experiments).
  explicit Topic(const Participant& participant, std::string_view name = MessageTraits<T>::topic)
      : entity_(detail::createTopic(participant.handle(), MessageTraits<T>::descriptor(), name)) {}

  std::int32_t handle() const { return entity_.handle(); }

 private:
  Entity entity_;
};

}  // namespace pool::net
