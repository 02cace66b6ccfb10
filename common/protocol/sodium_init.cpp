// libsodium's one-time initialisation.
#include "protocol/sodium_init.h"

#include <sodium.h>

#include <stdexcept>

namespace pool::protocol {

void initSodium() {
  static const bool ready = sodium_init() >= 0;
  if (!ready) throw std::runtime_error("libsodium could not be initialised");
}

}  // namespace pool::protocol
