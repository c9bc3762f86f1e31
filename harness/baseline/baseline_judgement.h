#pragma once
// A run's results held against its expectation files, in deqp-runner's
// words: an expected failure or a known flake does not fail the gate; an
// unexpected failure does; a failure that passes on a rerun is a Flake,
// counted and listed; a known failure that now passes is an improvement
// (its line should be deleted); a known failure whose case did not run is
// reported as absent.
#include <ostream>
#include <string>
#include <vector>

#include "baseline/expectation_file.h"
#include "runner/case_result.h"

namespace snell {

enum class Outcome {
  Pass,            // not a failure, and not listed as one
  ExpectedFail,    // failed with the status its fails line names
  KnownFlake,      // failed, and a flakes pattern matches
  Flake,           // failed unexpectedly, then passed on a rerun
  UnexpectedPass,  // listed as a known failure, and did not fail
  UnexpectedFail,  // failed, not as listed (or not listed at all)
};

const char* outcomeName(Outcome outcome);

struct JudgedCase {
  const CaseResult* result = nullptr;
  Outcome outcome = Outcome::Pass;
  const KnownFailure* knownFailure = nullptr;  // its fails line, if any
  const CasePattern* flakePattern = nullptr;   // the flakes line that matched, if any
};

struct AbsentCase {
  std::string backend;
  const KnownFailure* entry = nullptr;
};

struct SkippedCase {
  std::string backend, caseId;
  const CasePattern* pattern = nullptr;
};

struct BaselineReport {
  std::vector<JudgedCase> cases;  // one per result, in the results' order
  std::vector<AbsentCase> absent;
  std::vector<SkippedCase> skipped;

  std::size_t count(Outcome outcome) const;
  // Whether the gate fails: any unexpected failure.
  bool failed() const { return count(Outcome::UnexpectedFail) > 0; }
};

// Whether `result` is a failure its backend's expectations do not account
// for: the cases a run reruns. Ignores reruns already made.
bool isUnexpectedFailure(const ExpectationSet& expectations, const CaseResult& result);

// `skipped`: the cases the skips files kept out of the run. The report
// points into `expectations` and `results`, which must outlive it.
BaselineReport judgeResults(const ExpectationSet& expectations,
                            const std::vector<CaseResult>& results,
                            std::vector<SkippedCase> skipped);

// What a person must act on: unexpected failures with the line to add,
// flakes, improvements with the line to delete, absent cases, skips.
void printBaselineReport(std::ostream& out, const ExpectationSet& expectations,
                         const BaselineReport& report);

}  // namespace snell
