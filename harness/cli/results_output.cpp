#include "cli/results_output.h"

#include <fmt/format.h>
#include <string.h>

#include <filesystem>
#include <iostream>
#include <map>

#include "baseline/results_csv.h"
#include "cli/shell_word.h"
#include "core/atomic_file.h"
#include "report/junit.h"
#include "report/phase_summary.h"
#include "report/summary_table.h"
#include "runner/interrupt_flag.h"
#include "runner/json_fields.h"

namespace snell::cli {
namespace {

void printWorstSlack(const std::vector<CaseResult>& results) {
  std::map<std::string, double> worst;
  std::map<std::string, std::size_t> checked;
  for (const CaseResult& r : results) {
    worst[r.backend] = std::max(worst[r.backend], r.worstSlack());
    for (const VaryingCheck& v : r.varyings) checked[r.backend] += v.checked;
  }
  // A backend that checked no vector has no slack to speak of (0.000 would
  // read as a perfect score).
  for (const auto& [backend, slack] : worst)
    if (checked[backend] > 0) fmt::print("{}: worst slack {:.3f}\n", backend, slack);
}

}  // namespace

std::string asLines(const std::string& message) {
  return message.empty() || message.back() == '\n' ? message : message + "\n";
}

int reportResults(const std::vector<CaseResult>& results, const ExpectationSet& expectations,
                  const std::vector<SkippedCase>& skipped, const ResultsOutput& output) {
  const BaselineReport report = judgeResults(expectations, results, skipped);
  const std::string incomplete =
      output.interruptedBy
          ? fmt::format("interrupted by {} after {} of {} results",
                        signalName(output.interruptedBy), results.size(), output.planned)
          : output.incompleteBecause;
  if (!output.json.empty())
    writeFileAtomically(std::filesystem::path(output.json).replace_extension(".csv"),
                        toResultsCsv(report));
  RunTiming timing =
      summarizeTiming(results, output.wallSeconds, output.workers, output.crossApiSeconds);
  timing.oracleStore = output.oracleStore;
  if (!output.json.empty() && output.wallSeconds > 0)
    writeFileAtomically(std::filesystem::path(output.json).replace_extension(".timing.json"),
                        jsonText(runTimingJson(timing), 2) + "\n");
  if (!output.junit.empty()) {
    JUnitNotes notes = junitNotesOf(report);
    notes.incomplete = incomplete;
    writeFileAtomically(output.junit, toJUnitXml(results, notes));
  }

  printSummaryTable(std::cout, results);
  printWorstSlack(results);
  if (output.wallSeconds > 0) printRunTiming(std::cout, timing);
  // Failures first, with why; then what passes with a story to tell: the
  // diagnostics of listings that must not compile, and why a backend is
  // not supported.
  for (const JudgedCase& c : report.cases)
    if (c.outcome == Outcome::UnexpectedFail)
      fmt::print("\n{} on {}: {}\n{}", c.result->caseId, c.result->backend,
                 statusName(c.result->status), asLines(c.result->message));
  for (const CaseResult& r : results)
    if (r.status == Status::ExpectedCompileError || r.status == Status::NotSupported)
      fmt::print("\n{} on {}: {}: {}", r.caseId, r.backend, statusName(r.status),
                 asLines(r.message));
  if (!expectations.empty() || report.count(Outcome::Flake) > 0) {
    printBaselineReport(std::cout, expectations, report);
  }
  if (output.interruptedBy) {
    if (output.json.empty())
      fmt::print("\nsnell: {}; without --json no results were kept to go on from\n", incomplete);
    else
      fmt::print(
          "\nsnell: {}; the results written are marked incomplete: to go on, run the same "
          "command with --resume {} added\n",
          incomplete, shellWord(output.json));
    return 130;
  }
  return report.failed() ? 1 : 0;
}

}  // namespace snell::cli
