// `snell report RESULTS... -o DIR [--sweep SWEEP]`: the self-contained HTML
// report.
#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <system_error>

#include "backends/backend_registry.h"
#include "baseline/results_file.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cli/output_paths.h"
#include "core/errors.h"
#include "core/message.h"
#include "report/html_report.h"

namespace snell::cli {

Command addReportCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "report", "Write a self-contained HTML report (tolerance report, heat maps, comparisons)");
  struct Options {
    std::vector<std::string> results;
    std::string out;
    std::string images = "snell-out";
    std::string shaders = defaultShadersDir();
    std::string sweep;
    std::string golden = defaultGoldenDir();
  };
  auto options = std::make_shared<Options>();
  sub->add_option("results", options->results,
                  "Results files (snell run --json or merge), shown side by side in this order")
      ->required()
      ->check(CLI::ExistingFile);
  sub->add_option("-o,--out", options->out, "Folder to write index.html to")
      ->required()
      ->check(nonEmptyPath());
  sub->add_option("--images", options->images,
                  "The last run's --out folder: its rendered images and references (default: "
                  "snell-out)")
      ->check(nonEmptyPath());
  sub->add_option("--shaders", options->shaders, "Folder of listings (titles, fail thresholds)")
      ->check(CLI::ExistingDirectory);
  sub->add_option("--golden", options->golden,
                  "The last run's golden folder: its comparisons with goldens are pictured "
                  "(default: the repository's)")
      ->check(CLI::ExistingDirectory);
  sub->add_option("--sweep", options->sweep,
                  "A `snell sweep --out` folder: each listing's breaks and the sweep's charts "
                  "beside it")
      ->check(CLI::ExistingDirectory);
  return [options] {
    const auto start = std::chrono::steady_clock::now();
    checkOutputs({}, {{"-o", options->out}});
    const std::filesystem::path page = std::filesystem::path(options->out) / "index.html";
    for (const std::string& file : options->results) {
      std::error_code error;
      if (std::filesystem::equivalent(page, file, error))
        throw UsageError(
            fmt::format("{}: is the page this report would write (-o {}); give the "
                        "report another folder",
                        file, options->out));
    }
    std::vector<ReportRun> runs;
    for (const std::string& file : options->results) {
      bool incomplete = false;
      std::vector<CaseResult> results = readFinishedResultsFile(file, &incomplete);
      runs.push_back({file, std::move(results), incomplete});
    }
    const std::vector<Manifest> manifests = loadManifests(options->shaders);
    ReportOptions report;
    report.imagesDir = options->images;
    report.catalog = expandCases(manifests, "");
    report.sweepDir = options->sweep;
    report.goldenDir = options->golden;
    for (const BackendEntry& entry : backendRegistry().entries())
      report.goldenKeys[entry.name] = entry.goldenKey;
    report.title = fmt::format("{}", fmt::join(options->results, ", "));
    // A report that fails leaves no folder behind that it made itself.
    const std::filesystem::path made = firstMissingFolder(options->out);
    const ReportStats stats = [&] {
      try {
        return writeHtmlReport(runs, report, options->out);
      } catch (...) {
        std::error_code ignored;
        if (!made.empty()) std::filesystem::remove_all(made, ignored);
        throw;
      }
    }();
    if (stats.imagesMissing)
      printMessage(stderr,
                   "snell: note: {} holds none of these runs' images, so the report shows no "
                   "picture or heat map; pass --images the run's --out folder\n",
                   options->images);
    if (stats.otherRunsImages)
      printMessage(stderr,
                   "snell: note: {} holds another run's images of {} result(s) of the last run "
                   "(their errors are not the ones it recorded), so the report does not show "
                   "them; pass --images the last run's --out folder\n",
                   options->images, stats.otherRunsImages);
    fmt::print(
        "{}/index.html: {} cases, {} histograms, {} heat maps, {} pictures, {:.1f} MB, "
        "{:.2f} s\n",
        options->out, stats.cases, stats.histograms, stats.heatMaps, stats.pictures,
        stats.bytes / 1e6,
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    return 0;
  };
}

}  // namespace snell::cli
