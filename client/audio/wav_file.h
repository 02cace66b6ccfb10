// Writes mono samples as a 16-bit PCM WAV file.
#pragma once

#include <cstddef>
#include <span>
#include <string>

#include "core/result.h"

namespace pool::audio {

/// Writes `samples` (clamped to [-1, 1]) at `rate` Hz to `path`. Fails with one line naming the
/// file. Returns the bytes written.
Result<std::size_t> writeWav(const std::string& path, std::span<const float> samples, int rate);

}  // namespace pool::audio
