// Topics, readers and writers on the Cyclone DDS C API: QoS, writing, taking, matching, liveliness.
#include <dds/dds.h>

#include <algorithm>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "core/hex.h"
#include "net/dds_detail.h"
#include "net/sample.h"

namespace pool::net::detail {

namespace {

using QosPtr = std::unique_ptr<dds_qos_t, decltype(&dds_delete_qos)>;

QosPtr makeQos(const QosProfile& p, bool for_writer) {
  QosPtr qos(dds_create_qos(), &dds_delete_qos);
  // Readers and writers default differently (best effort vs reliable): always set both.
  dds_qset_reliability(qos.get(),
                       p.reliability == Reliability::Reliable ? DDS_RELIABILITY_RELIABLE
                                                              : DDS_RELIABILITY_BEST_EFFORT,
                       p.max_blocking.count());
  dds_qset_durability(qos.get(), p.durability == Durability::TransientLocal
                                     ? DDS_DURABILITY_TRANSIENT_LOCAL
                                     : DDS_DURABILITY_VOLATILE);
  if (p.keepAll()) {
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_ALL, 0);
  } else {
    dds_qset_history(qos.get(), DDS_HISTORY_KEEP_LAST, static_cast<int32_t>(p.history_depth));
  }
  // Readers keep the default infinite lease, which accepts whatever lease a writer offers.
  if (for_writer && p.liveliness_lease) {
    dds_qset_liveliness(qos.get(), DDS_LIVELINESS_AUTOMATIC, p.liveliness_lease->count());
  }
  if (for_writer) {
    dds_qset_writer_data_lifecycle(qos.get(), p.autodispose);
  }
  return qos;
}

InstanceState instanceStateOf(dds_instance_state_t state) {
  switch (state) {
    case DDS_IST_NOT_ALIVE_DISPOSED:
      return InstanceState::Disposed;
    case DDS_IST_NOT_ALIVE_NO_WRITERS:
      return InstanceState::NoWriters;
    case DDS_IST_ALIVE:
      break;
  }
  return InstanceState::Alive;
}

SampleMeta metaOf(const dds_sample_info_t& info) {
  SampleMeta m;
  m.valid = info.valid_data;
  m.instance = instanceStateOf(info.instance_state);
  m.source_time_ns = info.source_timestamp;
  m.instance_handle = info.instance_handle;
  m.publication_handle = info.publication_handle;
  return m;
}

Status statusOf(dds_return_t rc, const char* what) {
  if (rc >= 0) {
    return Status::ok();
  }
  return Status{std::string(what) + ": " + dds_strretcode(rc)};
}

/// Gives loaned samples back to the reader however the scope is left.
struct LoanGuard {
  dds_entity_t reader;
  void** buffers;
  int32_t count;
  ~LoanGuard() {
    if (count > 0) {
      dds_return_loan(reader, buffers, count);
    }
  }
};

}  // namespace

std::int32_t createTopic(std::int32_t participant, const dds_topic_descriptor_t* descriptor,
                         std::string_view name) {
  const std::string topic_name(name);
  return check(dds_create_topic(participant, descriptor, topic_name.c_str(), nullptr, nullptr),
               "topic " + topic_name);
}

std::int32_t createWriter(std::int32_t participant, std::int32_t topic, const QosProfile& qos) {
  return check(dds_create_writer(participant, topic, makeQos(qos, true).get(), nullptr), "writer");
}

std::int32_t createReader(std::int32_t participant, std::int32_t topic, const QosProfile& qos) {
  return check(dds_create_reader(participant, topic, makeQos(qos, false).get(), nullptr), "reader");
}

Status write(std::int32_t writer, const void* sample) {
  return statusOf(dds_write(writer, sample), "write");
}

Status dispose(std::int32_t writer, const void* key_sample) {
  return statusOf(dds_dispose(writer, key_sample), "dispose");
}

Status unregister(std::int32_t writer, const void* key_sample) {
  return statusOf(dds_unregister_instance(writer, key_sample), "unregister");
}

std::size_t fetchInto(std::int32_t reader, bool take, void** samples, SampleMeta* metas,
                      std::size_t n) {
  std::vector<dds_sample_info_t> infos(n);
  const auto max = static_cast<uint32_t>(n);
  const dds_return_t rc = take ? dds_take(reader, samples, infos.data(), n, max)
                               : dds_read(reader, samples, infos.data(), n, max);
  check(rc, take ? "take" : "read");
  for (int32_t i = 0; i < rc; ++i) {
    metas[i] = metaOf(infos[static_cast<std::size_t>(i)]);
  }
  return static_cast<std::size_t>(rc);
}

std::size_t fetchLoaned(std::int32_t reader, bool take, std::size_t max,
                        const std::function<void(const void*, const SampleMeta&)>& each) {
  constexpr std::size_t kChunk = 64;
  std::size_t total = 0;
  while (total < max) {
    std::array<void*, kChunk> buffers{};  // a null first entry asks DDS for a loan
    std::array<dds_sample_info_t, kChunk> infos{};
    const std::size_t want = std::min(kChunk, max - total);
    const auto count = static_cast<uint32_t>(want);
    const dds_return_t rc = take ? dds_take(reader, buffers.data(), infos.data(), want, count)
                                 : dds_read(reader, buffers.data(), infos.data(), want, count);
    check(rc, take ? "take" : "read");
    const LoanGuard guard{reader, buffers.data(), rc};
    for (int32_t i = 0; i < rc; ++i) {
      const auto k = static_cast<std::size_t>(i);
      each(buffers[k], metaOf(infos[k]));
    }
    total += static_cast<std::size_t>(rc);
    // A read returns the same samples again: one chunk is all it can do.
    if (static_cast<std::size_t>(rc) < want || !take) {
      break;
    }
  }
  return total;
}

MatchedStatus publicationMatched(std::int32_t writer) {
  dds_publication_matched_status_t s{};
  check(dds_get_publication_matched_status(writer, &s), "publication matched status");
  return {s.current_count, s.total_count};
}

MatchedStatus subscriptionMatched(std::int32_t reader) {
  dds_subscription_matched_status_t s{};
  check(dds_get_subscription_matched_status(reader, &s), "subscription matched status");
  return {s.current_count, s.total_count};
}

std::vector<std::uint64_t> matchedPublications(std::int32_t reader) {
  std::vector<dds_instance_handle_t> handles(16);
  for (;;) {
    // Returns how many are matched, filling at most handles.size(): a larger count asks again.
    const std::int32_t n = check(
        dds_get_matched_publications(reader, handles.data(), handles.size()), "matched writers");
    if (static_cast<std::size_t>(n) <= handles.size()) {
      handles.resize(static_cast<std::size_t>(n));
      break;
    }
    handles.resize(static_cast<std::size_t>(n));
  }
  std::vector<std::uint64_t> out(handles.begin(), handles.end());
  std::sort(out.begin(), out.end());
  return out;
}

std::string participantOf(std::int32_t reader, std::uint64_t publication) {
  dds_builtintopic_endpoint_t* data = dds_get_matched_publication_data(reader, publication);
  if (data == nullptr) return {};
  std::string out = hexOf(data->participant_key.v);
  dds_builtintopic_free_endpoint(data);
  return out;
}

std::string guidOf(std::int32_t entity) {
  dds_guid_t guid{};
  if (dds_get_guid(entity, &guid) != DDS_RETCODE_OK) return {};
  return hexOf(guid.v);
}

LivelinessStatus livelinessChanged(std::int32_t reader) {
  dds_liveliness_changed_status_t s{};
  check(dds_get_liveliness_changed_status(reader, &s), "liveliness changed status");
  return {s.alive_count, s.not_alive_count, s.alive_count_change, s.not_alive_count_change,
          s.last_publication_handle};
}

bool waitForMatches(std::int32_t entity, bool is_writer, std::uint32_t count,
                    std::chrono::nanoseconds timeout) {
  // Polls rather than attaching the entity's status condition, whose status mask other waitsets
  // may rely on. The deadline is on the DDS clock; this is for start-up, not for hot paths.
  const dds_time_t deadline = dds_time() + timeout.count();
  for (;;) {
    const MatchedStatus s = is_writer ? publicationMatched(entity) : subscriptionMatched(entity);
    if (s.current >= count) {
      return true;
    }
    if (dds_time() >= deadline) {
      return false;
    }
    dds_sleepfor(DDS_MSECS(1));
  }
}

}  // namespace pool::net::detail
