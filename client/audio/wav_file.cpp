// RIFF/WAVE writer: one PCM chunk, mono, 16 bits, little-endian.
#include "client/audio/wav_file.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <vector>

namespace pool::audio {
namespace {

void put(std::vector<char>& out, std::uint32_t value, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((value >> (8 * i)) & 0xFF));
}

void tag(std::vector<char>& out, const char* four) {
  out.insert(out.end(), four, four + 4);
}

}  // namespace

Result<std::size_t> writeWav(const std::string& path, std::span<const float> samples, int rate) {
  const auto data_bytes = static_cast<std::uint32_t>(samples.size() * 2);
  std::vector<char> out;
  out.reserve(44 + data_bytes);
  tag(out, "RIFF");
  put(out, 36 + data_bytes, 4);
  tag(out, "WAVE");
  tag(out, "fmt ");
  put(out, 16, 4);  // chunk size
  put(out, 1, 2);   // PCM
  put(out, 1, 2);   // mono
  put(out, static_cast<std::uint32_t>(rate), 4);
  put(out, static_cast<std::uint32_t>(rate) * 2, 4);  // bytes per second
  put(out, 2, 2);                                     // block align
  put(out, 16, 2);                                    // bits per sample
  tag(out, "data");
  put(out, data_bytes, 4);
  for (float s : samples) {
    const auto v = static_cast<std::int16_t>(std::lround(std::clamp(s, -1.0f, 1.0f) * 32767.0f));
    put(out, static_cast<std::uint16_t>(v), 2);
  }
  std::ofstream file(path, std::ios::binary);
  if (!file) return Result<std::size_t>::fail(path + ": cannot open for writing");
  file.write(out.data(), static_cast<std::streamsize>(out.size()));
  if (!file) return Result<std::size_t>::fail(path + ": write failed");
  return Result<std::size_t>::ok(out.size());
}

}  // namespace pool::audio
