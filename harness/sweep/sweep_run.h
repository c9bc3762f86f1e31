#pragma once
// One whole sweep: the points on the oracle and on each driver, the breaks
// and their classes, the critical angles, and the Fresnel methods against
// physics.
#include <filesystem>
#include <string>
#include <vector>

#include "sweep/critical_angle.h"
#include "sweep/listing_sweep.h"
#include "sweep/method_sweep.h"
#include "sweep/sweep_classify.h"
#include "sweep/sweep_points.h"

namespace snell::sweep {

// The sweep's points as `snell eval` input, written to SweepOptions::outDir.
inline constexpr const char* kInputFile = "sweep-input.jsonl";

struct SweepOptions {
  std::string executable;               // the snell binary, whose `eval` runs each driver
  std::vector<std::string> backends;    // drivers; the oracle is always swept
  std::filesystem::path outDir;         // kInputFile goes here
  bool quick = false;                   // quickGrid() in place of fullGrid()
  double timeoutSeconds = 300;          // per driver child, and per listing draw
  std::vector<std::string> driverArgs;  // --device, --gl-provider, for every driver child
  std::vector<PrecisionRules> rules;    // each driver's API rules (for the listings' oracles)
  bool builtins = true;                 // refract() and reflect() themselves
  std::string listings = "*";           // glob over listing ids; empty: no listings
  std::filesystem::path shadersDir;     // the catalog
};

struct SweepResult {
  SweepGrid grid;
  std::vector<SweepPoint> points;
  std::vector<BackendSweep> sweeps;  // the oracle first, then each driver
  std::vector<Break> breaks;         // builtins, every backend
  std::vector<CriticalAngle> criticalAngles;
  std::vector<MethodSample> methodSamples;
  std::vector<Break> methodBreaks;  // Break::point indexes methodSamples
  bool listingsSwept = false;
  ListingSweepResult listings;
  double wallSeconds = 0;
};

SweepResult runSweep(const SweepOptions& options);

// What a file of this name in SweepOptions::outDir is to the sweep, which
// writes or removes it there besides sweep.json: its input, a driver's
// batch of points, the listings' job file, a chart or gnuplot's script or
// log (sweep_charts.h); empty when it is none of its own. (The charts'
// data is a folder of its own, kChartDataFolder.)
std::string ownFileRole(const std::string& name);

// Everything after the drivers have answered (for tests that bring their own
// observations).
void classifyAll(SweepResult& result);

}  // namespace snell::sweep
