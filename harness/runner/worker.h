#pragma once
// A worker process: `snell worker --backend B` reads case ids on standard
// input, one per line, runs each on its one backend and writes one JSON
// result line per case to standard output as soon as the case ends. The
// supervisor starts workers fresh (exec, never fork after a driver loaded),
// so a crash or a hang in a driver costs only the worker.
#include <string>

namespace snell {

struct WorkerOptions {
  std::string backend;
  std::string shaders;
  bool validation = false;
  std::string outDir;     // rendered images, heat maps and masks
  std::string goldenDir;  // empty: no golden comparison (bless)
};

// Returns the process exit code.
int runWorker(const WorkerOptions& options);

}  // namespace snell
