// `snell compare A B [C ...]`: each run against the one before it.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <set>

#include "baseline/compare_runs.h"
#include "baseline/results_file.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "core/errors.h"
#include "runner/json_fields.h"

namespace snell::cli {
namespace {

// FILE, or FILE@BACKEND where FILE@BACKEND is not itself a file.
RunSide readSide(const std::string& text) {
  RunSide side;
  side.label = text;
  std::string path = text;
  const auto at = text.rfind('@');
  if (!std::filesystem::exists(text) && at != std::string::npos) {
    path = text.substr(0, at);
    side.backend = text.substr(at + 1);
    if (side.backend.empty())
      throw UsageError(
          fmt::format("{}: name a backend after the @ (FILE@gl), or drop the @", text));
  }
  side.results = readFinishedResultsFile(path, &side.incomplete);
  if (!side.backend.empty() &&
      std::none_of(side.results.begin(), side.results.end(),
                   [&](const CaseResult& r) { return r.backend == side.backend; })) {
    std::set<std::string> backends;
    for (const CaseResult& r : side.results) backends.insert(r.backend);
    throw UsageError(fmt::format("{}: {} holds no results of backend `{}` (it holds {})", text,
                                 path, side.backend, fmt::join(backends, ", ")));
  }
  return side;
}

}  // namespace

Command addCompareCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "compare", "Compare runs: regressions, fixes, changes, new, removed, metric drift");
  struct Options {
    std::vector<std::string> runs;
    bool json = false;
    double drift = 2.0;
  };
  auto options = std::make_shared<Options>();
  sub->add_option("runs", options->runs,
                  "Results files (snell run --json), oldest first; FILE@gl selects one backend, "
                  "so FILE@gl FILE@vk compares the two halves of a run")
      ->required()
      // Two or more: the most CLI11 allows, so that its help says "..." and
      // not "x 2"; fewer than two is refused with the count.
      ->expected(
          2,
          CLI::detail::expected_max_vector_size);  // CLI11 would print "TEXT x 2" for two or more
  sub->add_flag("--json", options->json, "Print the comparisons as JSON");
  sub->add_option("--drift", options->drift,
                  "Report a worst slack or image error that grew by more than this factor")
      ->check(CLI::Range(1.0, 1e12))
      ->check(notNan())
      ->capture_default_str();
  sub->footer(
      "Exit 1 when any comparison has a regression (a status worse than before), or when a "
      "later run was interrupted (the cases it did not reach were not checked).");
  return [options] {
    std::vector<RunSide> sides;
    for (const std::string& run : options->runs) sides.push_back(readSide(run));
    DriftRule rule;
    rule.factor = options->drift;
    nlohmann::json all = nlohmann::json::array();
    bool regressed = false;
    std::vector<std::string> interrupted;
    for (std::size_t k = 1; k < sides.size(); ++k) {
      const RunComparison c = compareRuns(sides[k - 1], sides[k], rule);
      regressed = regressed || !c.regressions.empty();
      // A gate on `compare old new` must not pass on a run cut short: the
      // cases it did not reach may fail (merge and run say the same).
      if (sides[k].incomplete)
        interrupted.push_back(fmt::format("{} ({} case(s) of {} not reached)", sides[k].label,
                                          c.notReached.size(), sides[k - 1].label));
      if (options->json)
        all.push_back(comparisonToJson(c));
      else
        printComparison(std::cout, c, rule);
    }
    if (options->json) std::cout << jsonText(all, 2) << "\n";
    if (!interrupted.empty())
      fmt::print(stderr,
                 "snell compare: exit 1: {} is an interrupted run, and the gate does not pass "
                 "on one; finish it (`snell run --resume FILE.partial`) or run it again\n",
                 fmt::join(interrupted, "; "));
    return regressed || !interrupted.empty() ? 1 : 0;
  };
}

}  // namespace snell::cli
