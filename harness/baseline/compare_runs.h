#pragma once
// Two runs side by side, in piglit's words: each result present in both is
// a regression (status worse), a fix (better), a change (a backend enabled
// or disabled: NotSupported on one side) or unchanged, by the status the
// gate goes by (a flake's is Pass); the others are new or removed. Metric drift: a worst slack or
// an image error against the reference that grew by more than a stated factor, whatever the status.
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "runner/case_result.h"

namespace snell {

// One side of a comparison: a results file, or one backend of it
// (`FILE@BACKEND`, so the OpenGL and Vulkan halves of one run compare case
// by case).
struct RunSide {
  std::string label;    // as given
  std::string backend;  // empty: every backend, results keyed by backend and case
  std::vector<CaseResult> results;
  // An interrupted run (its records marked incomplete, or a FILE.partial):
  // a result it lacks was not reached, not removed.
  bool incomplete = false;
};

// Values below these floors are noise, not drift: a slack under 1 % of the
// allowance, an image error under 2^-20 (a few fp32 ULP of a [0, 1] colour).
struct DriftRule {
  double factor = 2.0;
  double slackFloor = 0.01;
  double imageFloor = 0x1p-20;
};

struct StatusChange {
  std::string key;  // "backend case", or the case when both sides name a backend
  Status from = Status::Pass, to = Status::Pass;
};

struct Drift {
  std::string key;
  std::string metric;  // "worst slack", "image error vs reference" (or golden, other-backend:A/B)
  double from = 0, to = 0;
};

struct RunComparison {
  std::string from, to;
  std::vector<StatusChange> regressions, fixes, changes;
  // Results of the later run that failed and then passed on a rerun, from
  // the first status to the rerun's that passed: flakes, which pass the
  // gate as `run` and `merge` judge them. Each side is judged by its gate
  // status.
  std::vector<StatusChange> flakes;
  std::vector<std::string> added, removed;  // piglit's "new" and "removed"
  std::vector<std::string> notReached;      // lacking from an interrupted later run
  // Results whose listing's text (listing_digest) differs between the runs:
  // a shader author's edit, to which a change of status may be owed rather
  // than to the driver.
  std::vector<std::string> listingEdited;
  std::vector<Drift> drift;
  std::size_t unchanged = 0;
};

// Throws UsageError when one side names a backend and the other does not.
RunComparison compareRuns(const RunSide& from, const RunSide& to, const DriftRule& rule);

void printComparison(std::ostream& out, const RunComparison& comparison, const DriftRule& rule);
nlohmann::json comparisonToJson(const RunComparison& comparison);

}  // namespace snell
