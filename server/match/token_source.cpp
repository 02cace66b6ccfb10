// Seat tokens, seeds and hex ids.
#include "server/match/token_source.h"

namespace pool::server {

std::uint64_t TokenSource::token() {
  std::uint64_t t = 0;
  while (t == 0) t = engine_();
  return t;
}

std::uint64_t randomSeed() {
  std::random_device device;
  return (static_cast<std::uint64_t>(device()) << 32) ^ device();
}

std::string randomHex(TokenSource& source, int digits) {
  static constexpr char kHex[] = "0123456789abcdef";
  std::string out;
  for (int i = 0; i < digits; ++i) out += kHex[source.next() & 0xF];
  return out;
}

}  // namespace pool::server
