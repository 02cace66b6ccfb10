// libsodium's one-time initialisation, shared by key generation and command signing.
#pragma once

namespace pool::protocol {

/// Initialises libsodium once per process (thread-safe); throws std::runtime_error if it cannot.
void initSodium();

}  // namespace pool::protocol
