#pragma once
// A results file as `snell run --json` writes it (JSON Lines, one record
// per case and backend), read back for merge, resume, compare and report.
#include <filesystem>
#include <string>
#include <vector>

#include "runner/case_result.h"

namespace snell {

// Throws UsageError with FILE:LINE for a missing file or a malformed record.
// A torn last line (a run killed mid-write of FILE.partial) is dropped.
std::vector<CaseResult> readResultsFile(const std::filesystem::path& path);

// The JSON Lines text of `results`; `incomplete` marks every record as part
// of a run that was interrupted before all its cases finished.
std::string toResultsJsonLines(const std::vector<CaseResult>& results, bool incomplete = false);

// "backend case": results are unique by this key within a run.
std::string resultKey(const CaseResult& result);

}  // namespace snell
