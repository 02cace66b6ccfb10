// libFuzzer target: the table-spec parser on any text, then the geometry of a spec it accepts.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

#include "broken_promise.h"
#include "table/table_geometry.h"
#include "table/table_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto spec = pool::table::parseTableSpec(text, "fuzz.json", "/nonexistent", "fuzz");
  if (!spec) {
    pool::fuzz::expectOneLineReason(spec.error());
    return 0;
  }
  // An accepted spec has a real playing surface; pool-tablegen and the physics build on it.
  if (!(std::isfinite(spec->length) && spec->length > 0 && std::isfinite(spec->width) &&
        spec->width > 0)) {
    pool::fuzz::brokenPromise("accepted a spec without a playing surface");
  }
  pool::table::buildTableGeometry(*spec);
  return 0;
}
