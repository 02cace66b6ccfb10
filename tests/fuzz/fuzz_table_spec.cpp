// libFuzzer target: the table-spec parser on any text, and the geometry built from a spec it
// accepts.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "table/table_geometry.h"
#include "table/table_spec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const auto spec = pool::table::parseTableSpec(text, "fuzz.json", "/nonexistent", "fuzz");
  if (!spec) {
    const std::string& why = spec.error();
    if (why.empty() || why.find('\n') != std::string::npos) {
      std::fprintf(stderr, "refusal is not one line: '%s'\n", why.c_str());
      std::abort();
    }
    return 0;
  }
  // An accepted spec has a real playing surface; pool-tablegen and the physics build on it.
  if (!(std::isfinite(spec->length) && spec->length > 0 && std::isfinite(spec->width) &&
        spec->width > 0)) {
    std::fprintf(stderr, "accepted a spec without a playing surface\n");
    std::abort();
  }
  pool::table::buildTableGeometry(*spec);
  return 0;
}
