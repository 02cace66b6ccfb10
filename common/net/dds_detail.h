// Untyped calls into the Cyclone DDS C API that the typed templates of common/net forward to.
// Internal to common/net: other code uses Participant, Topic, Writer, Reader, WaitSet, Sample.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

#include "net/dds_error.h"
#include "net/qos_profiles.h"
#include "pool.h"

namespace pool::net {

struct SampleMeta;

/// How many remote readers a writer is matched with (or writers a reader is).
struct MatchedStatus {
  std::uint32_t current = 0;  ///< matched now
  std::uint32_t total = 0;    ///< ever matched
};

/// A reader's view of its writers' liveliness. The change counts are since the last query.
struct LivelinessStatus {
  std::uint32_t alive = 0;      ///< writers alive now
  std::uint32_t not_alive = 0;  ///< writers whose lease ran out (and not deleted)
  std::int32_t alive_change = 0;
  std::int32_t not_alive_change = 0;
  std::uint64_t last_publication_handle = 0;  ///< the writer that changed last
};

namespace detail {

/// Throws DdsError("<what>: <DDS message>") when rc < 0; returns rc otherwise.
std::int32_t check(std::int32_t rc, std::string_view what);

void* allocZeroed(std::size_t bytes);
void freeBuffer(void* buffer);
void freeSampleContents(void* sample, const dds_topic_descriptor_t* descriptor);

std::int32_t createTopic(std::int32_t participant, const dds_topic_descriptor_t* descriptor,
                         std::string_view name);
/// `parent`: a participant, or a publisher (writers) or subscriber (readers) with partitions.
std::int32_t createWriter(std::int32_t parent, std::int32_t topic, const QosProfile& qos);
std::int32_t createReader(std::int32_t parent, std::int32_t topic, const QosProfile& qos);

Status write(std::int32_t writer, const void* sample);
Status dispose(std::int32_t writer, const void* key_sample);
Status unregister(std::int32_t writer, const void* key_sample);

/// Takes (or reads) up to n samples into caller-owned zeroed samples; returns how many.
std::size_t fetchInto(std::int32_t reader, bool take, void** samples, SampleMeta* metas,
                      std::size_t n);
/// Takes (or reads) up to max samples on loan, calls `each` on every one, returns the loan.
std::size_t fetchLoaned(std::int32_t reader, bool take, std::size_t max,
                        const std::function<void(const void*, const SampleMeta&)>& each);

MatchedStatus publicationMatched(std::int32_t writer);
/// The participant of writer `publication` matched with `reader`, as 32 hex digits (its GUID), or
/// empty when that writer is not matched (gone, or never seen).
std::string participantOf(std::int32_t reader, std::uint64_t publication);
/// The GUID of `entity` in hex, as participantOf writes a participant's; empty on failure.
std::string guidOf(std::int32_t entity);
MatchedStatus subscriptionMatched(std::int32_t reader);
/// The publication handles of the writers matched with `reader` now, in ascending order.
std::vector<std::uint64_t> matchedPublications(std::int32_t reader);
LivelinessStatus livelinessChanged(std::int32_t reader);
/// Blocks until `entity` (a writer or reader) matches at least `count` peers or `timeout` passes.
bool waitForMatches(std::int32_t entity, bool is_writer, std::uint32_t count,
                    std::chrono::nanoseconds timeout);

}  // namespace detail
}  // namespace pool::net
