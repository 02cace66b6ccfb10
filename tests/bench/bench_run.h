// How every benchmark runs: the suite's smoke run (short, POOL_BENCH_SMOKE=1) and an exit that
// fails on any benchmark's error.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <string_view>
#include <vector>

#include "support/ci_env.h"

namespace pool::bench {

/// True in the test suite's smoke run (POOL_BENCH_SMOKE=1, set by tests/bench/CMakeLists.txt):
/// each benchmark does its work once or twice at a small size, to prove it runs and reports, not
/// to measure. Read at registration time too, so a benchmark's repetitions can depend on it.
inline bool smoke() {
  const char* env = std::getenv("POOL_BENCH_SMOKE");
  return env != nullptr && std::string_view(env) == "1";
}

/// `full` outside the smoke run, `small` in it.
template <class T>
T smokeOr(T full, T small) {
  return smoke() ? small : full;
}

/// Repetitions for a benchmark whose median is reported: `n`, or 2 in the smoke run (the fewest
/// for which the library computes a median).
inline int reps(int n) {
  return smokeOr(n, 2);
}

/// The console table, remembering every benchmark that reported an error (SkipWithError).
class CheckedReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs) {
      if (r.error_occurred) errors_.push_back(r.benchmark_name() + ": " + r.error_message);
    }
    ConsoleReporter::ReportRuns(runs);
  }

  /// 0 when no benchmark reported an error, else 1 after naming each on stderr.
  int exitCode() const {
    for (const std::string& e : errors_) std::fprintf(stderr, "benchmark error: %s\n", e.c_str());
    if (!errors_.empty()) std::fprintf(stderr, "%zu benchmark(s) failed\n", errors_.size());
    return errors_.empty() ? 0 : 1;
  }

 private:
  std::vector<std::string> errors_;
};

/// A benchmark program's main: runs what the command line selects through `reporter` and exits
/// non-zero on an unknown argument or on any benchmark's error.
inline int runBenchmarks(int argc, char** argv, CheckedReporter& reporter) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 2;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return reporter.exitCode();
}

}  // namespace pool::bench
