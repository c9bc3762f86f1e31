#include <fmt/format.h>

#include <iostream>
#include <map>

#include "cli/commands.h"
#include "cli/suite_session.h"
#include "core/atomic_file.h"
#include "report/junit.h"
#include "report/summary_table.h"

namespace snell::cli {
namespace {

void printThroughput(const std::vector<CaseResult>& results) {
  std::map<std::string, std::pair<std::size_t, double>> perBackend;  // vectors, seconds
  std::map<std::string, double> worst;
  for (const CaseResult& r : results) {
    perBackend[r.backend].first += r.vectorsChecked();
    perBackend[r.backend].second += r.backendSeconds;
    worst[r.backend] = std::max(worst[r.backend], r.worstSlack());
  }
  for (const auto& [backend, totals] : perBackend)
    fmt::print("{}: {} vectors checked, {:.0f} per second of backend time (compile, draw, read back), "
               "worst slack {:.3f}\n",
               backend, totals.first, totals.second > 0 ? totals.first / totals.second : 0.0,
               worst[backend]);
}

int run(const SuiteOptions& options, const std::string& junit) {
  const SuiteRun suite = runSuite(options, false, true);
  const std::vector<CaseResult>& results = suite.results;
  if (!junit.empty()) writeFileAtomically(junit, toJUnitXml(results));

  printSummaryTable(std::cout, results);
  printThroughput(results);
  // Failures first, with why; then what passes with a story to tell: the
  // diagnostics of listings that must not compile, and why a backend is
  // not supported.
  bool failed = false;
  for (const CaseResult& r : results) {
    if (!isFailure(r.status)) continue;
    failed = true;
    fmt::print("\n{} on {}: {}\n{}", r.caseId, r.backend, statusName(r.status), r.message);
  }
  for (const CaseResult& r : results)
    if (r.status == Status::ExpectedCompileError || r.status == Status::NotSupported)
      fmt::print("\n{} on {}: {}: {}{}", r.caseId, r.backend, statusName(r.status), r.message,
                 r.message.empty() || r.message.back() != '\n' ? "\n" : "");
  return failed ? 1 : 0;
}

}  // namespace

Command addRunCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("run", "Run the conformance cases and gate on the results");
  auto options = std::make_shared<SuiteOptions>();
  auto junit = std::make_shared<std::string>();
  addSuiteOptions(*sub, *options);
  sub->add_option("--junit", *junit, "Write results as JUnit XML");
  return [options, junit] { return run(*options, *junit); };
}

}  // namespace snell::cli
