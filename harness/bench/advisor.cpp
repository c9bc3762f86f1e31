#include "bench/advisor.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "core/errors.h"

namespace snell::bench {

std::vector<Advice> advise(const BenchResults& results, const std::string& scene, double budget,
                           const std::string& metric, const std::string& backend) {
  // `snell bench` measures one scene, the one its physics reference models.
  if (scene != results.scene)
    throw UsageError(fmt::format(
        "the results measure scene `{}`, not `{}`: ask about `{}` (`snell bench` measures "
        "the sphere, which its reference models)",
        results.scene, scene, results.scene));
  if (!std::isfinite(budget) || budget < 0)
    throw UsageError(fmt::format("--budget {}: give a finite error of 0 or more", budget));
  errorMetric(ImageError{}, metric);  // an unknown metric throws here
  std::set<std::string> measured, backends;
  for (const BenchRecord& r : results.records) {
    measured.insert(r.backend);
    if (backend.empty() || r.backend == backend) backends.insert(r.backend);
  }
  if (backends.empty())
    throw UsageError(fmt::format("backend `{}` was not measured in these results; they measure {}",
                                 backend, fmt::join(measured, ", ")));

  std::vector<Advice> out;
  for (const std::string& name : backends) {
    std::vector<BenchRecord> within;
    Advice advice;
    advice.backend = name;
    for (const BenchRecord& r : results.records) {
      if (r.backend != name) continue;
      if (errorMetric(r.error, metric) <= budget) within.push_back(r);
      if (!advice.mostAccurate ||
          errorMetric(r.error, metric) < errorMetric(advice.mostAccurate->error, metric))
        advice.mostAccurate = r;
    }
    std::stable_sort(within.begin(), within.end(), [](const BenchRecord& a, const BenchRecord& b) {
      return a.msPerFrame() < b.msPerFrame();
    });
    if (!within.empty()) {
      advice.choice = within[0];
      advice.mostAccurate.reset();
    }
    if (within.size() > 1) advice.runnerUp = within[1];
    out.push_back(std::move(advice));
  }
  return out;
}

}  // namespace snell::bench
