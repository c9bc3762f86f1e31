#pragma once
// `snell merge` and `--resume`: results of several partial runs (shards, or
// an interrupted run and its continuation) joined into the one run they
// split, in the order an unsharded run writes.
#include <string>
#include <vector>

#include "core/case.h"
#include "runner/case_result.h"

namespace snell {

struct ResultsFile {
  std::string path;
  std::vector<CaseResult> results;
};

// Backends in name order, cases in catalog order (an unsharded run's
// order). Throws UsageError for a result found twice or a case the catalog
// does not have.
std::vector<CaseResult> mergeResults(const std::vector<ResultsFile>& files,
                                     const std::vector<Case>& catalog);

// The image cases of `results` whose backends' images have not been compared
// with each other yet (their backends ran in different shards): the
// cross-backend check runs on these after a merge, so splitting a run drops no check.
std::vector<Case> casesWithoutCrossCheck(const std::vector<Case>& catalog,
                                         const std::vector<CaseResult>& results);

}  // namespace snell
