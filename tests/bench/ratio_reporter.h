// A console reporter that also prints each benchmark's median against a baseline from the same run.
#pragma once

#include <benchmark/benchmark.h>

#include "bench_run.h"

#include <cstdio>
#include <map>
#include <string>

namespace pool::bench {

/// Prints the usual table, then "name: median cpu X ms (Y× faster than baseline)" lines where
/// the baseline is the benchmark whose name starts with `baseline_prefix`. With `wall_clock` the
/// medians are of real time (work that waits on a disk), not CPU time.
class RatioReporter : public CheckedReporter {
 public:
  explicit RatioReporter(std::string baseline_prefix, bool wall_clock = false)
      : baseline_(std::move(baseline_prefix)), wall_clock_(wall_clock) {}

  void ReportRuns(const std::vector<Run>& runs) override {
    CheckedReporter::ReportRuns(runs);
    for (const Run& r : runs) {
      if (r.aggregate_name != "median") continue;
      const double time = wall_clock_ ? r.GetAdjustedRealTime() : r.GetAdjustedCPUTime();
      medians_[r.run_name.function_name] =
          time * benchmark::GetTimeUnitMultiplier(benchmark::kMillisecond) /
          benchmark::GetTimeUnitMultiplier(r.time_unit);
    }
  }

  /// The median (ms) of the benchmark named `name`; 0 if it did not run.
  double median(const std::string& name) const {
    const auto it = medians_.find(name);
    return it == medians_.end() ? 0.0 : it->second;
  }

  void Finalize() override {
    ConsoleReporter::Finalize();
    double base = 0;
    for (const auto& [name, ms] : medians_) {
      if (name.rfind(baseline_, 0) == 0) base = ms;
    }
    std::printf("\nmedian %s time per run, and speed-up against %s*:\n",
                wall_clock_ ? "wall-clock" : "CPU", baseline_.c_str());
    for (const auto& [name, ms] : medians_) {
      std::printf("  %-40s %10.3f ms", name.c_str(), ms);
      if (base > 0 && ms > 0) std::printf("   x%.1f", base / ms);
      std::printf("\n");
    }
  }

 private:
  std::string baseline_;
  bool wall_clock_ = false;
  std::map<std::string, double> medians_;
};

}  // namespace pool::bench
