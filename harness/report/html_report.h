#pragma once
// `snell report`: one self-contained HTML file (every image and chart
// embedded, no network) from one or more runs' results: a summary by
// listing and backend, the comparison matrix of every run and backend, the
// drivers, and per case the tolerance report (slack per output and its
// histogram, the worst samples, image errors, masked pixels by reason) with
// the reference, rendered and heat-map images side by side, and a heat map
// for every pair of backends that rendered the case; with a sweep, where
// each listing breaks (per backend and class) and the sweep's charts.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "core/case.h"
#include "runner/case_result.h"

namespace snell {

struct ReportRun {
  std::string label;
  std::vector<CaseResult> results;
  // An interrupted run (or a killed run's FILE.partial): its cases not
  // reached are missing, which the page says at its top.
  bool incomplete = false;
};

struct ReportOptions {
  // The run's --out folder: rendered images (<case>/<backend>.exr, .png),
  // the reference and the mask. Missing images are left out of the report.
  std::filesystem::path imagesDir;
  std::vector<Case> catalog;  // for titles, sources and fail thresholds
  std::string title;
  // A `snell sweep --out` folder: each listing's breaks beside it. Empty: none.
  std::filesystem::path sweepDir;
  // The golden folder the last run compared with, and each backend's golden
  // key in it: a comparison with a golden is pictured as the reference's
  // is. Empty: none pictured.
  std::filesystem::path goldenDir;
  std::map<std::string, std::string> goldenKeys;
};

struct ReportStats {
  std::size_t cases = 0, histograms = 0, heatMaps = 0, pictures = 0;
  // Results of the last run whose images in --images are another run's
  // (and so are not shown).
  std::size_t otherRunsImages = 0;
  // The runs have image cases and --images held none of their images.
  bool imagesMissing = false;
  std::size_t bytes = 0;
};

// Writes outDir/index.html (charts are drawn in outDir/work, removed after).
// Throws SetupError when gnuplot is missing or fails, UsageError when the
// sweep's JSON is missing or malformed.
ReportStats writeHtmlReport(const std::vector<ReportRun>& runs, const ReportOptions& options,
                            const std::filesystem::path& outDir);

}  // namespace snell
