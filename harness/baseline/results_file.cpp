#include "baseline/results_file.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "runner/case_result_json.h"

namespace snell {

std::vector<CaseResult> readResultsFile(const std::filesystem::path& path,
                                        ResultsFileState* state) {
  if (std::filesystem::is_directory(path))
    throw UsageError(
        fmt::format("{}: is a folder; give a results file written by "
                    "`snell run --json`",
                    path.string()));
  std::ifstream in(path);
  if (!in)
    throw UsageError(
        fmt::format("{}: cannot read this file; give a results file written by "
                    "`snell run --json`",
                    path.string()));
  std::vector<CaseResult> results;
  int number = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      const nlohmann::json record = nlohmann::json::parse(line);
      results.push_back(caseResultFromJson(record));
      if (state && record.is_object() && record.value("incomplete", false))
        state->incomplete = true;
    } catch (const nlohmann::json::exception& error) {
      // A run killed while writing leaves a last line with no newline: what
      // came before it is whole, and that case simply did not finish.
      if (in.eof()) {
        if (state) state->tornLine = number;
        break;
      }
      throw UsageError(
          fmt::format("{}:{}: not a snell result record ({}); give a file written by "
                      "`snell run --json`",
                      path.string(), number, readableError(error)));
    }
  }
  return results;
}

std::vector<CaseResult> readFinishedResultsFile(const std::filesystem::path& path,
                                                bool* incomplete) {
  ResultsFileState state;
  std::vector<CaseResult> results = readResultsFile(path, &state);
  if (state.tornLine > 0) {
    // Only a run's FILE.partial can be torn (the results file is renamed
    // into place whole): --resume finishes it into FILE.
    const std::string file = path.string();
    const std::string partial = kPartialSuffix;
    const bool isPartial = file.size() > partial.size() &&
                           file.compare(file.size() - partial.size(), partial.size(), partial) == 0;
    throw UsageError(fmt::format(
        "{}:{}: the last record is cut off (a run killed while writing it); {}", file,
        state.tornLine,
        isPartial ? fmt::format("finish the run with `snell run --resume {} --json {}` and the "
                                "run's own options",
                                file, file.substr(0, file.size() - partial.size()))
                  : std::string("give a whole results file")));
  }
  if (results.empty())
    throw UsageError(
        fmt::format("{}: holds no results; give a results file written by "
                    "`snell run --json`",
                    path.string()));
  if (state.incomplete)
    fmt::print(stderr,
               "snell: note: {} is an interrupted run (its records are marked incomplete): the "
               "cases it did not reach are missing from it\n",
               path.string());
  if (incomplete) *incomplete = state.incomplete;
  return results;
}

std::string toResultsJsonLines(const std::vector<CaseResult>& results, bool incomplete) {
  std::string text;
  for (const CaseResult& r : results) {
    nlohmann::json j = toJson(r);
    if (incomplete) j["incomplete"] = true;
    text += j.dump() + "\n";
  }
  return text;
}

std::string resultKey(const CaseResult& result) { return result.backend + " " + result.caseId; }

}  // namespace snell
