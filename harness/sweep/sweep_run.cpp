#include "sweep/sweep_run.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <system_error>

#include "core/errors.h"
#include "runner/interrupt_flag.h"
#include "sweep/sweep_backend_run.h"
#include "sweep/sweep_charts.h"

namespace snell::sweep {

void classifyAll(SweepResult& result) {
  result.breaks = classifySweep(result.points, result.sweeps);
  result.criticalAngles.clear();
  for (const BackendSweep& sweep : result.sweeps)
    for (CriticalAngle& c : criticalAngles(result.points, result.sweeps.front(), sweep))
      result.criticalAngles.push_back(c);
  result.methodSamples = methodSweep(result.grid);
  result.methodBreaks = classifyMethods(result.methodSamples);
}

namespace {

// Between the sweep's phases: a Ctrl-C stops the drivers' children at once
// (sweep_backend_run.cpp, listing_capture.cpp) and the sweep here.
void stopIfInterrupted(const std::filesystem::path& input) {
  const int signal = interruptReceived();
  if (signal == 0) return;
  std::error_code ignored;
  std::filesystem::remove(input, ignored);
  throw Interrupted(signal, fmt::format("sweep interrupted by {}: sweep.json and the charts are "
                                        "written when the sweep ends, so none was written, and "
                                        "its input and temporary files are removed",
                                        signalName(signal)));
}

}  // namespace

std::string ownFileRole(const std::string& name) {
  if (name == kInputFile) return "its input";
  if (name.starts_with(kBatchPrefix)) return "a driver's batch of points";
  if (name == kListingJobFile) return "the listings' job file";
  return chartFileRole(name);
}

SweepResult runSweep(const SweepOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  SweepResult result;
  result.grid = options.quick ? quickGrid() : fullGrid();
  result.points = options.builtins ? sweepPoints(result.grid) : std::vector<SweepPoint>{};
  result.sweeps.push_back(sweepOracle(result.points));
  std::filesystem::create_directories(options.outDir);
  const std::filesystem::path input = options.outDir / kInputFile;
  {
    std::ofstream file(input);
    file << evalInput(result.points);
    if (!file) throw SetupError(input.string() + ": cannot write the sweep's input; check --out");
  }
  for (const std::string& backend : options.backends) {
    result.sweeps.push_back(
        options.builtins ? sweepDriver(options.executable, backend, result.points, options.outDir,
                                       options.timeoutSeconds, 40, options.driverArgs)
                         : BackendSweep{backend, "", {}});
    stopIfInterrupted(input);
  }
  classifyAll(result);
  if (!options.listings.empty()) {
    ListingSweepOptions listing;
    listing.executable = options.executable;
    listing.backends = options.backends;
    listing.rules = options.rules;
    listing.driverArgs = options.driverArgs;
    listing.shadersDir = options.shadersDir;
    listing.filter = options.listings == "*" ? "" : options.listings;
    listing.outDir = options.outDir;
    listing.quick = options.quick;
    listing.timeoutSeconds = options.timeoutSeconds;  // --timeout cuts each draw too
    result.listings = runListingSweep(listing);
    stopIfInterrupted(input);
    result.listingsSwept = true;
  }
  result.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace snell::sweep
