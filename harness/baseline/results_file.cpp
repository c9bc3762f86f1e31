#include "baseline/results_file.h"

#include <fmt/format.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "core/errors.h"
#include "runner/case_result_json.h"

namespace snell {

std::vector<CaseResult> readResultsFile(const std::filesystem::path& path) {
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
      results.push_back(caseResultFromJson(nlohmann::json::parse(line)));
    } catch (const nlohmann::json::exception& error) {
      // A run killed while writing leaves a last line with no newline: what
      // came before it is whole, and that case simply did not finish.
      if (in.eof()) break;
      throw UsageError(
          fmt::format("{}:{}: not a snell result record ({}); give a file written by "
                      "`snell run --json`",
                      path.string(), number, error.what()));
    }
  }
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
