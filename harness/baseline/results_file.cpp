#include "baseline/results_file.h"

#include <fmt/format.h>

#include <fstream>
#include <map>
#include <nlohmann/json.hpp>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/message.h"
#include "runner/case_result_json.h"
#include "runner/json_fields.h"

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
  std::map<std::string, int> lineOf;  // by resultKey
  int number = 0;
  std::string line;
  while (std::getline(in, line)) {
    ++number;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    try {
      const nlohmann::json record = nlohmann::json::parse(line);
      results.push_back(caseResultFromJson(record));
      const auto [first, added] = lineOf.emplace(resultKey(results.back()), number);
      if (!added)
        throw UsageError(fmt::format(
            "{}:{}: a second result of {} on {} (the first is line {}); a run writes each case "
            "once per backend: give a file written by `snell run --json` or `snell merge`",
            path.string(), number, results.back().caseId, results.back().backend, first->second));
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

std::vector<CaseResult> readFinishedResultsFile(const std::filesystem::path& path, bool* incomplete,
                                                EmptyResults empty) {
  ResultsFileState state;
  std::vector<CaseResult> results = readResultsFile(path, &state);
  // A run's FILE.partial is renamed into place whole when the run ends:
  // one still there is a run that was killed.
  const std::string file = path.string();
  const std::string partial = kPartialSuffix;
  const bool isPartial = file.size() > partial.size() && file.ends_with(partial);
  if (state.tornLine > 0) {
    // Only a run's FILE.partial can be torn: --resume finishes it into FILE.
    throw UsageError(fmt::format(
        "{}:{}: the last record is cut off (a run killed while writing it); {}", file,
        state.tornLine,
        isPartial ? fmt::format("finish the run with `snell run --resume {} --json {}` and the "
                                "run's own options",
                                file, file.substr(0, file.size() - partial.size()))
                  : std::string("give a whole results file")));
  }
  if (results.empty() && empty == EmptyResults::Allowed) {
    if (incomplete) *incomplete = isPartial;
    return results;
  }
  if (results.empty())
    throw UsageError(
        fmt::format("{}: holds no results; give a results file written by "
                    "`snell run --json`",
                    path.string()));
  if (isPartial)
    printMessage(stderr,
                 "snell: note: {} is the results of a run that was killed: the cases it did not "
                 "reach are missing from it (finish it with `snell run --resume {} --json {}` and "
                 "the run's own options)\n",
                 file, file, file.substr(0, file.size() - partial.size()));
  else if (state.incomplete)
    printMessage(stderr,
                 "snell: note: {} is an interrupted run (its records are marked incomplete): the "
                 "cases it did not reach are missing from it\n",
                 path.string());
  if (incomplete) *incomplete = state.incomplete || isPartial;
  return results;
}

std::string toResultsJsonLines(const std::vector<CaseResult>& results, bool incomplete) {
  std::string text;
  for (const CaseResult& r : results) {
    nlohmann::json j = toJson(r);
    if (incomplete) j["incomplete"] = true;
    text += jsonText(j) + "\n";
  }
  return text;
}

std::string resultKey(const CaseResult& result) { return result.backend + " " + result.caseId; }

}  // namespace snell
