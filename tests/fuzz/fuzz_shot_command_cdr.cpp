// libFuzzer target: the server's receive path for ShotCommand bytes (CDR normalise and read), then
// validateShotCommand on whatever sample the bytes decode to.
#include <cstddef>
#include <cstdint>

#include "net/sample.h"
#include "net/shot_command_check.h"
#include "shot_command_cdr.h"
#include "shot_command_verdict.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pool::net::Sample<pool_ShotCommand> sample;  // frees what the read allocated
  if (!pool::fuzz::decodeShotCommand(data, size, *sample)) return 0;
  pool::fuzz::checkVerdict(*sample, pool::net::validateShotCommand(*sample));
  return 0;
}
