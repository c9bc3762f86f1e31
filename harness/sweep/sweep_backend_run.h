#pragma once
// Runs the sweep's points on the oracle (in process, the CPU) and on a
// driver through a `snell eval --backend NAME` child process: the same probe
// path as `snell eval`, every point of a function in one draw, and a driver
// that crashes or hangs takes only its child with it (its points become
// crash breaks and the sweep goes on).
#include <filesystem>
#include <string>
#include <vector>

#include "oracle/precision_rules.h"
#include "sweep/sweep_observation.h"
#include "sweep/sweep_points.h"

namespace snell::sweep {

// The oracle as a backend: its fp32 evaluation of the defining formula,
// judged against its own interval (GLSL rules).
BackendSweep sweepOracle(const std::vector<SweepPoint>& points);

// The points as `snell eval` input, one JSON line each (exact fp32 values).
std::string evalInput(const std::vector<SweepPoint>& points);

// Each child's input in the work folder: PREFIX<children left>-<points>.jsonl.
inline constexpr const char* kBatchPrefix = "sweep-input-";

// `executable` is the snell binary; each child's input is written to
// `workDir` and removed after. When a child crashes, the points it left
// unanswered are run again in halves (at most `maxChildren` children in
// all), so the crash is pinned to the point that causes it; a child that
// hangs past `timeoutSeconds` is killed and its points are not retried.
// `driverArgs` go to every child (--device, --gl-provider).
BackendSweep sweepDriver(const std::string& executable, const std::string& backend,
                         const std::vector<SweepPoint>& points,
                         const std::filesystem::path& workDir, double timeoutSeconds,
                         int maxChildren = 40, const std::vector<std::string>& driverArgs = {});

// One answer line of `snell eval` on a driver, as an observation (used by
// sweepDriver; exposed for tests).
Observation observationFromAnswer(const std::string& line);

}  // namespace snell::sweep
