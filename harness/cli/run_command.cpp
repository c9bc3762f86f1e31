#include <chrono>

#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cli/output_paths.h"
#include "cli/results_output.h"
#include "cli/suite_session.h"

namespace snell::cli {

Command addRunCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("run", "Run the conformance cases and gate on the results");
  auto options = std::make_shared<SuiteOptions>();
  auto junit = std::make_shared<std::string>();
  addSuiteOptions(*sub, *options);
  options->reruns = 1;
  sub->add_option("--junit", *junit, "Write results as JUnit XML")->check(nonEmptyPath());
  sub->add_option("--expectations", options->expectations,
                  "Known failures, flakes and skips: a folder of BACKEND-fails.txt, "
                  "-flakes.txt, -skips.txt, or one PREFIX-fails.txt (its siblings are read too)")
      ->check(nonEmptyPath());
  sub->add_option("--reruns", options->reruns,
                  "Times an unexpected failure is run again; one that passes is a Flake")
      ->check(wholeNumber())
      ->check(CLI::Range(0, 100))
      ->capture_default_str();
  // Given empty (unset CI variables), every job would run the whole suite.
  sub->add_option("--shard", options->shard,
                  "Run shard I of N (1-based, interleaved): --shard $CI_NODE_INDEX/$CI_NODE_TOTAL")
      ->check(CLI::Validator(
          [](const std::string& text) -> std::string {
            return text.empty() || text == "/"
                       ? "empty (are the CI variables unset?); give I/N, or leave the option out"
                       : "";
          },
          ""));
  sub->add_option("--resume", options->resume,
                  "Results file (or FILE.partial) of an interrupted run: its finished cases are "
                  "kept, the others run")
      ->check(CLI::ExistingFile);
  return [options, junit] {
    const auto start = std::chrono::steady_clock::now();
    std::vector<OutputPath> files;
    if (!options->json.empty()) files = resultsFileOutputs("--json", options->json);
    if (!junit->empty()) files.push_back({"--junit", *junit});
    std::vector<OutputPath> inputs = {{"--golden", options->golden}};
    if (!options->expectations.empty()) inputs.push_back({"--expectations", options->expectations});
    checkOutputs(files, {{"--out", options->out}}, inputs);
    checkNotGoldenFiles(files, {"--golden", options->golden});
    const SuiteRun suite = runSuite(*options, false, true);
    return reportResults(
        suite.results, suite.expectations, suite.skipped,
        {options->json, *junit, suite.interruptedBy, suite.planned,
         std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
         suite.workers, suite.crossApiSeconds, suite.oracleStore, ""});
  };
}

}  // namespace snell::cli
