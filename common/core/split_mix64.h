// SplitMix64: a tiny generator whose sequence is fixed by its seed on every platform.
#pragma once

#include <cstdint>

namespace pool {

/// The SplitMix64 output function applied to `x` advanced by one step: the value a generator
/// seeded with `x` returns first. Also a good 64-bit mixing (hash) function.
constexpr std::uint64_t splitMix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

/// A SplitMix64 generator (Steele, Lea and Flood 2014): the same seed, the same sequence on every
/// machine and standard library.
class SplitMix64 {
 public:
  explicit SplitMix64(std::uint64_t seed) : state_(seed) {}

  /// The next 64 random bits.
  std::uint64_t next() {
    const std::uint64_t out = splitMix64(state_);
    state_ += 0x9e3779b97f4a7c15ULL;
    return out;
  }

  /// Uniform in [0, 1): the top 53 bits make every double on a 2^-53 grid equally likely.
  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  /// Uniform in [0, n), n > 0, without modulo bias.
  std::uint64_t below(std::uint64_t n) {
    const std::uint64_t threshold = (0 - n) % n;
    for (;;) {
      const std::uint64_t r = next();
      if (r >= threshold) return r % n;
    }
  }

 private:
  std::uint64_t state_;
};

}  // namespace pool
