// A ShotCommand's serialized form as it travels: the 4-byte encapsulation header, then CDR.
#pragma once

#include <dds/ddsi/ddsi_cdrstream.h>

#include <cstddef>
#include <cstdint>
#include <vector>

#include "net/messages.h"

namespace pool::fuzz {

/// Encapsulation identifiers (big-endian on the wire) of an @appendable type: XCDR2, delimited
/// (the type's ops need XCDR2; Cyclone sends nothing else for it).
inline constexpr std::uint16_t kDCdr2Be = 0x0008, kDCdr2Le = 0x0009;

/// Reads bytes into `out` (zeroed) as Cyclone's default serdata does a received sample: the header
/// picks the version and byte order, normalisation checks every bound, then the sample is read.
/// False when the bytes are refused (`out` is then untouched).
inline bool decodeShotCommand(const std::uint8_t* data, std::size_t size, pool_ShotCommand& out) {
  if (size < 4) return false;
  const auto id = static_cast<std::uint16_t>(data[0] << 8 | data[1]);
  const std::size_t padding = data[3] & 3u;
  if (id != kDCdr2Be && id != kDCdr2Le) return false;
  if (size - 4 < padding) return false;
  constexpr std::uint32_t xcdr = 2;
  const bool swap = (id & 1u) == 0;  // big-endian on a little-endian host
  std::vector<char> payload(data + 4, data + size - padding);
  payload.push_back(0);  // never an empty buffer; not counted in the size below
  const auto payload_size = static_cast<std::uint32_t>(payload.size() - 1);
  const std::uint32_t* ops = pool_ShotCommand_desc.m_ops;
  std::uint32_t used = 0;
  if (!dds_stream_normalize_data(payload.data(), &used, payload_size, swap, xcdr, ops)) {
    return false;
  }
  dds_istream_t in;
  dds_istream_init(&in, used, payload.data(), xcdr);
  dds_stream_read(&in, reinterpret_cast<char*>(&out), ops);
  dds_istream_fini(&in);
  return true;
}

/// A command serialized as this build's writers send it: little-endian XCDR2.
inline std::vector<std::uint8_t> encodeShotCommand(const pool_ShotCommand& command) {
  dds_ostream_t os;
  dds_ostream_init(&os, 0, 2);
  dds_stream_write(&os, reinterpret_cast<const char*>(&command), pool_ShotCommand_desc.m_ops);
  std::vector<std::uint8_t> bytes{0, kDCdr2Le, 0, 0};
  bytes.insert(bytes.end(), os.m_buffer, os.m_buffer + os.m_index);
  dds_ostream_fini(&os);
  return bytes;
}

}  // namespace pool::fuzz
