#pragma once
// What `run` and `merge` print and write once the results are in: the
// summary, the failures with their reasons, the expectations report, the
// deqp-runner results.csv beside the JSON Lines, and JUnit.
#include <string>
#include <vector>

#include "baseline/baseline_judgement.h"
#include "runner/case_result.h"

namespace snell::cli {

struct ResultsOutput {
  std::string json;   // the JSON Lines file (already written); results.csv goes beside it
  std::string junit;  // empty: none
  int interruptedBy = 0;
  std::size_t planned = 0;
  // `run` only (merge has no timing of its own): the wall time, the
  // workers and the supervisor's images across APIs. wallSeconds 0: none.
  double wallSeconds = 0;
  int workers = 0;
  double crossApiSeconds = 0;
  std::string oracleStore;  // where oracle results were kept; empty: nowhere
  // `merge` of an interrupted shard: why the results are incomplete, for
  // the JUnit notes (run says it from interruptedBy). Empty: complete.
  std::string incompleteBecause;
};

// A result's message as the last lines of a block: ending in a newline, so
// what is printed next starts a line of its own.
std::string asLines(const std::string& message);

// Returns the exit code: 130 when interrupted, 1 for an unexpected failure, else 0.
int reportResults(const std::vector<CaseResult>& results, const ExpectationSet& expectations,
                  const std::vector<SkippedCase>& skipped, const ResultsOutput& output);

}  // namespace snell::cli
