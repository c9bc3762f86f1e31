#include "bench/ladder_checks.h"

#include <fmt/format.h>

#include <map>

namespace snell::bench {

double errorNoise(const std::string& metric) {
  // A tenth of an 8-bit step in linear RGB; a hundredth of a
  // just-noticeable difference in CIEDE2000.
  if (metric == "rms" || metric == "max") return 0.1 / 255.0;
  errorMetric({}, metric);  // refuses an unknown name
  return 0.01;
}

std::vector<std::string> wavelengthOrderViolations(const BenchResults& results,
                                                   const std::string& metric, double noise) {
  std::map<std::string, std::map<double, const BenchRecord*>> byBackend;
  for (const BenchRecord& r : results.records)
    if (const auto n = r.parameters.find("Wavelengths"); n != r.parameters.end())
      byBackend[r.backend][n->second] = &r;
  std::vector<std::string> violations;
  for (const auto& [backend, byCount] : byBackend)
    for (auto fewer = byCount.begin(); fewer != byCount.end(); ++fewer)
      for (auto more = std::next(fewer); more != byCount.end(); ++more) {
        const double fewerError = errorMetric(fewer->second->error, metric);
        const double moreError = errorMetric(more->second->error, metric);
        if (moreError > fewerError + noise)
          violations.push_back(fmt::format(
              "{}: {} wavelengths ({}) are farther from the reference than {} ({}): {} {:.5g} > "
              "{:.5g} + noise {:.3g}",
              backend, more->first, more->second->method, fewer->first, fewer->second->method,
              metric, moreError, fewerError, noise));
      }
  return violations;
}

}  // namespace snell::bench
