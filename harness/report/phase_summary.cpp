#include "report/phase_summary.h"

#include <fmt/format.h>
#include <fmt/ostream.h>

namespace snell {

double BackendTiming::vectorsPerSecond() const {
  return caseSeconds > 0 ? static_cast<double>(vectors) / caseSeconds : 0.0;
}

RunTiming summarizeTiming(const std::vector<CaseResult>& results, double wallSeconds, int workers,
                          double crossApiSeconds) {
  RunTiming timing{wallSeconds, workers, crossApiSeconds, {}, {}};
  for (const CaseResult& r : results) {
    BackendTiming& b = timing.backends[r.backend];
    ++b.cases;
    b.vectors += r.vectorsChecked();
    b.phases += r.phases;
    b.caseSeconds += r.seconds;
    b.oracleResults += r.oracleResults;
    b.oracleStored += r.oracleStored;
  }
  return timing;
}

void printRunTiming(std::ostream& out, const RunTiming& timing) {
  if (timing.backends.empty()) return;
  std::string header = fmt::format("{:<10}", "seconds");
  for (const auto& [name, b] : timing.backends) header += fmt::format(" {:>10}", name);
  fmt::print(out, "\n{}\n", header);
  for (Phase p : kAllPhases) {
    std::string row = fmt::format("{:<10}", phaseName(p));
    for (const auto& [name, b] : timing.backends) row += fmt::format(" {:>10.3f}", b.phases[p]);
    fmt::print(out, "{}\n", row);
  }
  std::string total = fmt::format("{:<10}", "total");
  for (const auto& [name, b] : timing.backends)
    total += fmt::format(" {:>10.3f}", b.phases.total());
  fmt::print(out, "{}\n", total);
  for (const auto& [name, b] : timing.backends)
    fmt::print(out,
               "{}: {} vectors checked, {:.0f} per second of case time (a case's every phase, "
               "the worker's start apart)\n",
               name, b.vectors, b.vectorsPerSecond());
  int results = 0, stored = 0;
  for (const auto& [name, b] : timing.backends) {
    results += b.oracleResults;
    stored += b.oracleStored;
  }
  if (timing.oracleStore.empty())
    // Off by the option, by SNELL_ORACLE_CACHE, or a folder that could not
    // be kept (which the run said when it started).
    fmt::print(out, "oracle results: {} computed, none kept (no oracle cache this run)\n", results);
  else
    // Read ones were computed by an earlier run, or by this one for
    // another backend under the same rules: the store cannot tell which.
    fmt::print(out,
               "oracle results: {} computed, {} read from {} (computed earlier: by an earlier "
               "run, or by this run for another backend)\n",
               results - stored, stored, timing.oracleStore);
  fmt::print(out,
             "wall {:.2f} s with {} worker{} (the phases are worker seconds); images across APIs "
             "{:.3f} s\n",
             timing.wallSeconds, timing.workers, timing.workers == 1 ? "" : "s",
             timing.crossApiSeconds);
}

nlohmann::json runTimingJson(const RunTiming& timing) {
  nlohmann::json backends = nlohmann::json::object();
  for (const auto& [name, b] : timing.backends) {
    nlohmann::json phases = nlohmann::json::object();
    for (Phase p : kAllPhases) phases[std::string(phaseName(p))] = b.phases[p];
    backends[name] = {{"cases", b.cases},
                      {"vectors", b.vectors},
                      {"case_seconds", b.caseSeconds},
                      {"vectors_per_second", b.vectorsPerSecond()},
                      {"oracle_results", b.oracleResults},
                      {"oracle_stored", b.oracleStored},
                      {"phases", phases}};
  }
  return {{"wall_seconds", timing.wallSeconds},
          {"workers", timing.workers},
          {"cross_api_seconds", timing.crossApiSeconds},
          {"oracle_store", timing.oracleStore},
          {"backends", backends}};
}

}  // namespace snell
