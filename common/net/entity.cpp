// Entity ownership, participants and the untyped Cyclone DDS calls the typed templates use.
#include "net/entity.h"

#include <dds/dds.h>

#include <cstring>
#include <string>

#include "net/dds_detail.h"
#include "net/participant.h"
#include "net/sample.h"

namespace pool::net {

DdsError::DdsError(const std::string& what, std::int32_t code)
    : std::runtime_error(what), code_(code) {}

Entity::~Entity() {
  reset();
}

Entity& Entity::operator=(Entity&& other) noexcept {
  if (this != &other) {
    reset();
    handle_ = other.handle_;
    other.handle_ = 0;
  }
  return *this;
}

void Entity::reset() {
  // Fails harmlessly when a parent was deleted first (it took this entity with it).
  if (handle_ > 0) {
    dds_delete(handle_);
  }
  handle_ = 0;
}

Participant::Participant(std::uint32_t domain) : domain_(domain) {
  if (domain > kMaxDomainId) {
    throw DdsError("participant: domain id " + std::to_string(domain) + " is not in 0-232",
                   DDS_RETCODE_BAD_PARAMETER);
  }
  entity_ = Entity(detail::check(dds_create_participant(domain, nullptr, nullptr), "participant"));
}

const char* toString(InstanceState state) {
  switch (state) {
    case InstanceState::Alive:
      return "alive";
    case InstanceState::Disposed:
      return "disposed";
    case InstanceState::NoWriters:
      return "no_writers";
  }
  return "unknown";
}

namespace detail {

std::int32_t check(std::int32_t rc, std::string_view what) {
  if (rc < 0) {
    throw DdsError(std::string(what) + ": " + dds_strretcode(rc), rc);
  }
  return rc;
}

void* allocZeroed(std::size_t bytes) {
  void* p = dds_alloc(bytes);
  std::memset(p, 0, bytes);
  return p;
}

void freeBuffer(void* buffer) {
  dds_free(buffer);
}

void freeSampleContents(void* sample, const dds_topic_descriptor_t* descriptor) {
  dds_sample_free(sample, descriptor, DDS_FREE_CONTENTS);
}

}  // namespace detail
}  // namespace pool::net
