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

}  // namespace snell
