#pragma once
// A results file as `snell run --json` writes it (JSON Lines, one record
// per case and backend), read back for merge, resume, compare and report.
#include <filesystem>
#include <string>
#include <vector>

#include "runner/case_result.h"

namespace snell {

// What a results file says of itself besides its records.
struct ResultsFileState {
  // Its last line was torn (a run killed mid-write): dropped from the records.
  int tornLine = 0;
  // Its records are marked incomplete: the run was interrupted.
  bool incomplete = false;
};

// Throws UsageError with FILE:LINE for a missing file, a folder, a
// malformed record or a second record of one case on one backend. A torn last line (a run killed
// mid-write of FILE.partial, which --resume reads) is dropped and reported in `state`.
std::vector<CaseResult> readResultsFile(const std::filesystem::path& path,
                                        ResultsFileState* state = nullptr);

// For a command that judges a finished run (compare, merge, report): the
// file must hold at least one record (unless `empty` allows none: a shard
// with no cases) and no torn line; an interrupted run, or the FILE.partial
// of one that was killed, is read with a note on stderr that its cases not
// reached are missing, and `incomplete` set.
enum class EmptyResults { Refused, Allowed };
std::vector<CaseResult> readFinishedResultsFile(const std::filesystem::path& path,
                                                bool* incomplete = nullptr,
                                                EmptyResults empty = EmptyResults::Refused);

// The JSON Lines text of `results`; `incomplete` marks every record as part
// of a run that was interrupted before all its cases finished.
std::string toResultsJsonLines(const std::vector<CaseResult>& results, bool incomplete = false);

// "backend case": results are unique by this key within a run.
std::string resultKey(const CaseResult& result);

}  // namespace snell
