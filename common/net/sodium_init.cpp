// libsodium's one-time initialisation.
#include "net/sodium_init.h"

#include <sodium.h>

#include <stdexcept>

namespace pool::net {

void initSodium() {
  static const bool ready = sodium_init() >= 0;
  if (!ready) throw std::runtime_error("libsodium could not be initialised");
}

}  // namespace pool::net
