// Publishers and subscribers with a partition QoS, on the Cyclone DDS C API.
#include "net/partition.h"

#include <dds/dds.h>

#include <memory>

#include "net/dds_detail.h"

namespace pool::net {

namespace {

using QosPtr = std::unique_ptr<dds_qos_t, decltype(&dds_delete_qos)>;

QosPtr partitionQos(const std::vector<std::string>& partitions) {
  QosPtr qos(dds_create_qos(), &dds_delete_qos);
  std::vector<const char*> names;
  names.reserve(partitions.size());
  for (const auto& name : partitions) names.push_back(name.c_str());
  dds_qset_partition(qos.get(), static_cast<uint32_t>(names.size()), names.data());
  return qos;
}

}  // namespace

Publisher::Publisher(const Participant& participant, const std::vector<std::string>& partitions)
    : entity_(detail::check(
          dds_create_publisher(participant.handle(), partitionQos(partitions).get(), nullptr),
          "publisher")) {}

Subscriber::Subscriber(const Participant& participant, const std::vector<std::string>& partitions)
    : entity_(detail::check(
          dds_create_subscriber(participant.handle(), partitionQos(partitions).get(), nullptr),
          "subscriber")) {}

}  // namespace pool::net
