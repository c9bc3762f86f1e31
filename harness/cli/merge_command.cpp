// `snell merge`: the results of a run split over shards or jobs, joined
// into one results file with its summary, results.csv and JUnit. The
// cross-backend image comparisons of cases whose backends ran in different
// jobs run here, so splitting a run drops no check.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <filesystem>
#include <optional>

#include "baseline/expectation_file.h"
#include "baseline/merge_results.h"
#include "baseline/results_file.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cli/output_paths.h"
#include "cli/results_output.h"
#include "compare/image_io.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/message.h"
#include "report/recorded_images.h"
#include "runner/cross_api_check.h"
#include "runner/image_check.h"

namespace snell::cli {

namespace {

// The images the pending cross-backend comparisons will read (pairs of
// backends that ran in different shards): a missing one means --out is not
// where the shards' images were gathered, which is the user's to fix
// (exit 2), not a difference between backends; so is an image that is not
// the one its shard recorded.
void requireImagesToCompare(const std::vector<BackendPair>& pairs,
                            const std::filesystem::path& out) {
  if (!pairs.empty() && !std::filesystem::is_directory(out))
    throw UsageError(
        fmt::format("{}: no such folder; the cross-backend comparisons need the "
                    "shards' images: gather their --out folders and pass --out DIR",
                    out.string()));
  for (const BackendPair& pair : pairs) {
    const std::string& id = pair.imageCase->id;
    const auto readable = [&](const std::filesystem::path& image) {
      if (!std::filesystem::is_regular_file(image))
        throw UsageError(fmt::format(
            "{}: missing, and the comparison of {} on {} and {} needs it; gather the shards' "
            "--out folders into one and pass it as --out DIR",
            image.string(), id, pair.a->backend, pair.b->backend));
      // A damaged copy would be compared as a difference between the
      // drivers (a CompatibilityWarning on both), which it is not.
      try {
        return readImage(image);
      } catch (const std::exception& error) {
        throw UsageError(fmt::format(
            "{}: cannot be read ({}), and the comparison of {} on {} and {} needs it; copy "
            "it again from the shard's --out folder",
            image.string(), error.what(), id, pair.a->backend, pair.b->backend));
      }
    };
    const std::vector<bool> masked = maskFlags(readable(maskImagePath(out, id)));
    const std::filesystem::path referencePath = referenceImagePath(out, id);
    const std::optional<Image> reference = std::filesystem::is_regular_file(referencePath)
                                               ? std::optional<Image>(readable(referencePath))
                                               : std::nullopt;
    for (const CaseResult* record : {pair.a, pair.b}) {
      const std::filesystem::path path = renderedImagePath(out, id, record->backend);
      const Image rendered = readable(path);
      // An image another run left there (an earlier pipeline's, another
      // job's) would be compared as this shard's: a divergence between the
      // drivers hidden, or one made up.
      if (!reference) continue;
      if (const auto other = differenceNotAsRecorded(*record, rendered, *reference, masked))
        throw UsageError(fmt::format(
            "{}: not the image the shard recorded for {} on {}: its largest difference from "
            "the reference beside it is {:.3g}, the shard recorded {:.3g}; it is another run's. "
            "Gather that shard's own --out folder into --out",
            path.string(), id, record->backend, other->there, other->recorded));
    }
  }
}

}  // namespace

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
  sub->add_option("--json", options->json,
                  "Merged results file (FILE.csv is written beside it: r.jsonl gives r.csv)")
      ->required()
      ->check(nonEmptyPath());
  sub->add_option("--junit", options->junit, "Write the merged results as JUnit XML")
      ->check(nonEmptyPath());
  sub->add_option("--shaders", options->shaders, "Folder of listings the shards ran")
      ->check(CLI::ExistingDirectory);
  sub->add_option("--out", options->out,
                  "Folder holding the shards' images (their --out folders, gathered), for the "
                  "cross-backend comparisons")
      ->check(nonEmptyPath());
  sub->add_option("--expectations", options->expectations,
                  "Known failures, flakes and skips, as for `snell run`")
      ->check(nonEmptyPath());
  return [options] {
    std::vector<OutputPath> outputs = resultsFileOutputs("--json", options->json);
    if (!options->junit.empty()) outputs.push_back({"--junit", options->junit});
    std::vector<OutputPath> inputs;
    for (const std::string& input : options->inputs)
      inputs.push_back({"the input " + input, input});
    checkInputsOnce(inputs);
    checkOutputs(outputs, {}, inputs);
    const std::vector<Manifest> manifests = loadManifests(options->shaders);
    const std::vector<Case> catalog = expandCases(manifests, "");
    std::vector<ResultsFile> files;
    std::vector<std::string> interrupted;  // the inputs of runs cut short
    for (const std::string& input : options->inputs) {
      bool inputIncomplete = false;
      // A shard may have no cases (more shards than cases): its file is
      // empty, and it is one of the shards all the same.
      files.push_back(
          {input, readFinishedResultsFile(input, &inputIncomplete, EmptyResults::Allowed)});
      if (inputIncomplete) interrupted.push_back(input);
    }
    const bool incomplete = !interrupted.empty();
    if (std::all_of(files.begin(), files.end(),
                    [](const ResultsFile& f) { return f.results.empty(); }))
      throw UsageError(
          fmt::format("{}: hold{} no results; give the results files of a run's "
                      "shards (snell run --json)",
                      fmt::join(options->inputs, ", "), options->inputs.size() == 1 ? "s" : ""));
    std::vector<CaseResult> results = mergeResults(files, catalog);
    std::vector<std::string> backends;
    for (const CaseResult& r : results)
      if (std::find(backends.begin(), backends.end(), r.backend) == backends.end())
        backends.push_back(r.backend);
    ExpectationSet expectations;
    if (!options->expectations.empty()) {
      expectations = loadExpectations(options->expectations, backends, todayUtc());
      std::vector<std::string> caseIds;
      for (const Case& c : catalog) caseIds.push_back(c.id);
      for (const std::string& note : entriesMatchingNoCase(expectations, caseIds))
        printMessage(stderr, "snell: note: {}\n", note);
    }
    requireImagesToCompare(pendingBackendPairs(catalog, results), options->out);
    checkAcrossApis(catalog, options->out, results);
    writeFileAtomically(options->json, toResultsJsonLines(results, incomplete));
    ResultsOutput output;
    output.json = options->json;
    output.junit = options->junit;
    output.planned = results.size();
    if (incomplete)
      output.incompleteBecause = fmt::format(
          "merged from a shard that was interrupted ({}): its cases not reached are missing",
          fmt::join(interrupted, ", "));
    const int code = reportResults(results, expectations, {}, output);
    // A gate on the merged results must not pass on cases that never ran.
    if (incomplete) {
      fmt::print(
          "\nsnell: {}; the merged results are marked incomplete: finish the shard (run it "
          "again with --resume FILE) and merge again\n",
          output.incompleteBecause);
      return std::max(code, 1);
    }
    return code;
  };
}

}  // namespace snell::cli
