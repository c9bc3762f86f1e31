#pragma once
// Where a run's time went: each backend's cases by phase (worker seconds,
// which add up across the workers running side by side), the run's wall
// time, and vectors per second with the oracle and the comparison counted.
#include <map>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "core/phase_clock.h"
#include "runner/case_result.h"

namespace snell {

struct BackendTiming {
  std::size_t cases = 0;
  std::size_t vectors = 0;
  PhaseTimes phases;       // start included
  double caseSeconds = 0;  // the cases' own wall time: every phase but start
  int oracleResults = 0;   // the oracle results the cases used
  int oracleStored = 0;    // of those, read from the oracle store
  // Vectors over the time spent on the cases that checked them, the oracle
  // and the comparison included; 0 when nothing was checked.
  double vectorsPerSecond() const;
};

struct RunTiming {
  double wallSeconds = 0;  // the whole run, start-up and the summary's input included
  int workers = 0;         // run side by side
  // Work of the supervisor itself after the cases: images across APIs.
  double crossApiSeconds = 0;
  std::string oracleStore;  // the folder of stored oracle results; empty: none
  std::map<std::string, BackendTiming> backends;
};

RunTiming summarizeTiming(const std::vector<CaseResult>& results, double wallSeconds, int workers,
                          double crossApiSeconds);

// A table, phases down and backends across, then the wall time.
void printRunTiming(std::ostream& out, const RunTiming& timing);

// The same as JSON: what `run --json FILE` writes to FILE.timing.json.
nlohmann::json runTimingJson(const RunTiming& timing);

}  // namespace snell
