#include "sweep/sweep_run.h"

#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include "core/atomic_file.h"
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
void stopIfInterrupted() {
  const int signal = interruptReceived();
  if (signal == 0) return;
  throw Interrupted(signal,
                    fmt::format("sweep interrupted by {}: sweep.json and the charts are written "
                                "when the sweep ends, so none was written, nor its input (an "
                                "earlier sweep's files in --out are as they were), and its "
                                "temporary files are removed",
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
  for (const std::string& backend : options.backends) {
    result.sweeps.push_back(
        options.builtins ? sweepDriver(options.executable, backend, result.points, options.outDir,
                                       options.timeoutSeconds, 40, options.driverArgs)
                         : BackendSweep{backend, "", {}});
    stopIfInterrupted();
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
    stopIfInterrupted();
    result.listingsSwept = true;
  }
  // The input goes with the sweep.json and charts written after it: put
  // in place whole once the sweep is done, so that a sweep stopped before
  // leaves an earlier one's input beside that one's results.
  writeFileAtomically(options.outDir / kInputFile, evalInput(result.points));
  result.wallSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace snell::sweep
