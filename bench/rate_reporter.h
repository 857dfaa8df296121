// bench/rate_reporter.h — the console reporter of spline_bench, iso_bench and ffd_bench:
// it prints like Google Benchmark's and keeps each benchmark's rate (one of the
// named counters; the median over repetitions when --benchmark_repetitions is
// given), for the summary table each program prints after the run.
#pragma once

#include <benchmark/benchmark.h>

#include <unistd.h>  // isatty

#include <algorithm>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace gllab::bench {

/// Whether the console reporter colours its output, as Google Benchmark decides
/// it: --benchmark_color=true|yes|1 or false|no|0, or auto (the default): when
/// stdout is a terminal. Read before benchmark::Initialize takes the flags.
inline bool console_color(int argc, char** argv) {
  bool color = isatty(STDOUT_FILENO) != 0;
  for (int k = 1; k < argc; ++k) {
    const std::string arg = argv[k];
    if (arg.rfind("--benchmark_color=", 0) == 0) {
      const std::string value = arg.substr(std::strlen("--benchmark_color="));
      color = value == "true" || value == "yes" || value == "1" || (value == "auto" && color);
    }
  }
  return color;
}

class RateReporter : public benchmark::ConsoleReporter {
 public:
  RateReporter(bool color, std::vector<std::string> counters)
      : ConsoleReporter(color ? OO_ColorTabular : OO_Tabular), counters_(std::move(counters)) {}
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred) continue;
      const bool iteration = run.run_type == Run::RT_Iteration;
      if (!iteration && run.aggregate_name != "median") continue;
      for (const std::string& name : counters_) {
        const auto c = run.counters.find(name);
        if (c == run.counters.end()) continue;
        if (iteration)
          rates_[run.run_name.function_name].push_back(c->second.value);
        else
          medians_[run.run_name.function_name] = c->second.value;
      }
    }
    ConsoleReporter::ReportRuns(runs);
  }
  /// The rate of a benchmark by its function name: the median row if there
  /// was one, else the middle of its iterations' rates; 0 if it did not run.
  double rate(const std::string& name) const {
    if (const auto m = medians_.find(name); m != medians_.end()) return m->second;
    const auto it = rates_.find(name);
    if (it == rates_.end()) return 0;
    std::vector<double> r = it->second;
    std::sort(r.begin(), r.end());
    return r[r.size() / 2];
  }

 private:
  std::vector<std::string> counters_;
  std::map<std::string, std::vector<double>> rates_;
  std::map<std::string, double> medians_;
};

}  // namespace gllab::bench
