#pragma once
// A worker process: `snell worker --backend B` reads case ids on standard
// input, one per line, runs each on its one backend and writes one JSON
// result line per case to standard output as soon as the case ends. The
// supervisor starts workers fresh (exec, never fork after a driver loaded),
// so a crash or a hang in a driver costs only the worker.
#include <nlohmann/json.hpp>
#include <string>

#include "backends/backend.h"

namespace snell {

struct WorkerOptions {
  std::string backend;  // a registered name (backends/backend_registry.h)
  std::string shaders;
  bool validation = false;
  std::string device;      // BackendOptions::device
  std::string glProvider;  // BackendOptions::glProvider
  // Bring the backend up, print its driver as one JSON line and exit: how
  // `run`, `devices` and `--version --drivers` learn whether a driver comes
  // up, without loading any driver themselves.
  bool describe = false;
  std::string outDir;      // rendered images, heat maps and masks
  std::string goldenDir;   // empty: no golden comparison (bless)
  std::string blessFlags;  // ImageCheckOptions::blessFlags
  // The run this worker belongs to: its workers share each case's CPU
  // reference image through outDir (runner/reference_cache.h). Empty: not shared.
  std::string runId;
  // When the supervisor spawned this worker (steady clock, nanoseconds):
  // the time until its driver is up is the first case's `start` phase.
  // 0: unknown, not charged.
  long long spawnedAtNs = 0;
  // Folder of oracle results kept across runs; empty: none.
  std::string oracleStore;
};

// The JSON a describing worker prints, as in a result's "driver".
nlohmann::json driverJson(const DriverInfo& driver);

// Returns the process exit code.
int runWorker(const WorkerOptions& options);

}  // namespace snell
