#pragma once
// `snell advise`: the cheapest measured method whose error stays within a
// budget, per backend, with the runner-up.
#include <optional>
#include <string>
#include <vector>

#include "bench/bench_record.h"

namespace snell::bench {

struct Advice {
  std::string backend;
  std::optional<BenchRecord> choice;        // the cheapest within budget
  std::optional<BenchRecord> runnerUp;      // the next cheapest within budget
  std::optional<BenchRecord> mostAccurate;  // when nothing is within budget: the nearest miss
};

// One Advice per backend in the results (or only `backend` when given).
// Throws UsageError when the scene is not the one measured, the metric is
// unknown, the budget is not a finite non-negative number, or the backend
// was not measured.
std::vector<Advice> advise(const BenchResults& results, const std::string& scene, double budget,
                           const std::string& metric, const std::string& backend = "");

}  // namespace snell::bench
