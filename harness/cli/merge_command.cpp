// `snell merge`: the results of a run split over shards or jobs, joined
// into one results file with its summary, results.csv and JUnit. The
// cross-backend image comparisons of cases whose backends ran in different
// jobs run here, so splitting a run drops no check.
#include <fmt/format.h>

#include <filesystem>

#include "baseline/expectation_file.h"
#include "baseline/merge_results.h"
#include "baseline/results_file.h"
#include "cli/commands.h"
#include "cli/results_output.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "runner/cross_api_check.h"

namespace snell::cli {

Command addMergeCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "merge", "Join the results of a run's shards into one results file, summary and JUnit");
  struct Options {
    std::vector<std::string> inputs;
    std::string json, junit, expectations;
    std::string shaders = defaultShadersDir();
    std::string out = "snell-out";
  };
  auto options = std::make_shared<Options>();
  sub->add_option("results", options->inputs, "Results files of the shards (snell run --json)")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("--json", options->json, "Merged results file (results.csv is written beside it)")
      ->required();
  sub->add_option("--junit", options->junit, "Write the merged results as JUnit XML");
  sub->add_option("--shaders", options->shaders, "Folder of listings the shards ran")
      ->check(CLI::ExistingDirectory);
  sub->add_option("--out", options->out,
                  "Folder holding the shards' images (their --out folders, gathered), for the "
                  "cross-backend comparisons");
  sub->add_option("--expectations", options->expectations,
                  "Known failures, flakes and skips, as for `snell run`");
  return [options] {
    const std::vector<Manifest> manifests = loadManifests(options->shaders);
    const std::vector<Case> catalog = expandCases(manifests, "");
    std::vector<ResultsFile> files;
    for (const std::string& input : options->inputs)
      files.push_back({input, readResultsFile(input)});
    std::vector<CaseResult> results = mergeResults(files, catalog);
    std::vector<std::string> backends;
    for (const CaseResult& r : results)
      if (std::find(backends.begin(), backends.end(), r.backend) == backends.end())
        backends.push_back(r.backend);
    ExpectationSet expectations;
    if (!options->expectations.empty())
      expectations = loadExpectations(options->expectations, backends, todayUtc());
    std::vector<Case> unchecked = casesWithoutCrossCheck(catalog, results);
    if (!unchecked.empty() && !std::filesystem::is_directory(options->out))
      throw UsageError(
          fmt::format("{}: no such folder; the cross-backend comparisons need the "
                      "shards' images: gather their --out folders and pass --out DIR",
                      options->out));
    checkAcrossApis(unchecked, options->out, results);
    writeFileAtomically(options->json, toResultsJsonLines(results));
    return reportResults(results, expectations, {},
                         {options->json, options->junit, 0, results.size(), 0, 0, 0, ""});
  };
}

}  // namespace snell::cli
