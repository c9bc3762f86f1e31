#include "cli/results_output.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <string.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <map>
#include <string>
#include <vector>

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

// Image cases held against the CPU reference only, their driver having no
// golden in --golden (a new driver, or a --golden folder that is not the
// one blessed into): said after the table, where a whole run of them passed
// with the fact inside each case's message only.
void printCasesWithoutGoldens(const std::vector<CaseResult>& results) {
  std::vector<const CaseResult*> without;
  for (const CaseResult& r : results) {
    const auto against = [&](const char* kind) {
      return std::any_of(r.images.begin(), r.images.end(),
                         [&](const ImageComparison& c) { return c.against == kind; });
    };
    // A failed case is reported as failed; bless refuses its image anyway.
    const bool passed = r.status == Status::Pass || r.status == Status::QualityWarning;
    if (passed && against("reference") && !against("golden")) without.push_back(&r);
  }
  if (without.empty()) return;
  std::vector<std::string> named;
  for (std::size_t k = 0; k < without.size() && k < 4; ++k)
    named.push_back(fmt::format("{} on {}", without[k]->caseId, without[k]->backend));
  if (without.size() > named.size())
    named.push_back(fmt::format("{} more", without.size() - named.size()));
  fmt::print(
      "\n{} image case(s) had no golden for their driver, so only the CPU reference gated "
      "them: {}; `snell bless` with this run's --shaders, --filter, --backend and --golden writes "
      "their "
      "goldens\n",
      without.size(), fmt::join(named, ", "));
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
  printCasesWithoutGoldens(results);
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
