// WaitSet and GuardCondition on the Cyclone DDS C API.
#include "net/waitset.h"

#include <dds/dds.h>

#include <algorithm>

namespace pool::net {

GuardCondition::GuardCondition(const Participant& participant)
    : entity_(detail::check(dds_create_guardcondition(participant.handle()), "guard condition")) {}

void GuardCondition::trigger() const {
  detail::check(dds_set_guardcondition(handle(), true), "guard condition trigger");
}

void GuardCondition::reset() const {
  detail::check(dds_set_guardcondition(handle(), false), "guard condition reset");
}

WaitSet::WaitSet(const Participant& participant)
    : entity_(detail::check(dds_create_waitset(participant.handle()), "waitset")) {}

void WaitSet::attach(const GuardCondition& guard, std::int64_t tag) {
  detail::check(dds_waitset_attach(entity_.handle(), guard.handle(), tag), "waitset attach");
  ++attached_;
}

void WaitSet::attachUnreadCondition(std::int32_t reader, std::int64_t tag) {
  // Holds while any sample (data or instance-state notice) has not been read or taken.
  Entity condition(
      detail::check(dds_create_readcondition(reader, DDS_NOT_READ_SAMPLE_STATE), "read condition"));
  detail::check(dds_waitset_attach(entity_.handle(), condition.handle(), tag), "waitset attach");
  conditions_.push_back(ReadCondition{reader, std::move(condition)});
  ++attached_;
}

void WaitSet::detachUnreadCondition(std::int32_t reader) {
  const auto it = std::find_if(conditions_.begin(), conditions_.end(),
                               [reader](const ReadCondition& c) { return c.reader == reader; });
  if (it == conditions_.end()) return;
  dds_waitset_detach(entity_.handle(), it->condition.handle());
  conditions_.erase(it);  // deletes the condition
  --attached_;
}

void WaitSet::attachLivelinessStatus(std::int32_t reader, std::int64_t tag) {
  // The reader's own status condition, narrowed to liveliness; data wakes through read conditions.
  detail::check(dds_set_status_mask(reader, DDS_LIVELINESS_CHANGED_STATUS), "status mask");
  detail::check(dds_waitset_attach(entity_.handle(), reader, tag), "waitset attach");
  ++attached_;
}

std::vector<std::int64_t> WaitSet::wait(std::chrono::nanoseconds timeout) const {
  std::vector<dds_attach_t> triggered(std::max<std::size_t>(attached_, 1));
  const dds_return_t rc = detail::check(
      dds_waitset_wait(entity_.handle(), triggered.data(), triggered.size(), timeout.count()),
      "waitset wait");
  const auto n = std::min(static_cast<std::size_t>(rc), triggered.size());
  return {triggered.begin(), triggered.begin() + static_cast<std::ptrdiff_t>(n)};
}

}  // namespace pool::net
