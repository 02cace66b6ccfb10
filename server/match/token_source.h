// Random numbers the lobby hands out: seat tokens, rack seeds, server ids.
#pragma once

#include <cstdint>
#include <random>
#include <string>

namespace pool::server {

/// A seeded generator of 64-bit values; tests pass a fixed seed, the server a random one.
class TokenSource {
 public:
  explicit TokenSource(std::uint64_t seed) : engine_(seed) {}

  /// A seat token: uniformly random, never 0 (0 means "no seat").
  std::uint64_t token();
  /// Any 64-bit value (rack seeds).
  std::uint64_t next() { return engine_(); }

 private:
  std::mt19937_64 engine_;
};

/// A seed from the operating system's entropy source.
std::uint64_t randomSeed();

/// `digits` lowercase hex digits from `source` (a server id).
std::string randomHex(TokenSource& source, int digits = 8);

}  // namespace pool::server
