#pragma once
// JUnit XML, the format CI systems (GitLab, Jenkins, GitHub) show natively.
#include <map>
#include <string>
#include <vector>

#include "baseline/baseline_judgement.h"
#include "runner/case_result.h"

namespace snell {

struct JUnitNotes {
  // Failures the expectation files account for, by "backend case": the
  // outcome and where it is listed. Shown as skipped (an expected failure)
  // or as a flaky pass, not as a failure.
  std::map<std::string, std::string> expectedFailures, flakes;
  // Non-empty for an interrupted run: why, and how much finished.
  std::string incomplete;
};

// Expected failures, known flakes and flakes of a judged run.
JUnitNotes junitNotesOf(const BaselineReport& report);

std::string toJUnitXml(const std::vector<CaseResult>& results, const JUnitNotes& notes = {});

}  // namespace snell
