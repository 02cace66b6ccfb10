// Whether the tests and benchmarks run in CI (CI=true), where what cannot run is a failure, not a
// skip.
#pragma once

#include <cstdlib>
#include <string_view>

namespace pool::test {

/// True when the CI environment variable is "true" (as GitHub Actions, GitLab CI and most other
/// CI services set it).
inline bool runningInCi() {
  const char* ci = std::getenv("CI");
  return ci != nullptr && std::string_view(ci) == "true";
}

}  // namespace pool::test
