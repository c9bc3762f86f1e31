#pragma once
// The supervisor behind `snell run`: it touches no graphics API. It starts
// worker processes (this binary, `snell worker`), hands them cases, and
// reads each result as the case ends. A worker past its case's time limit
// is killed (Timeout); a worker that dies gives its case Crash with the
// signal and the last lines of its stderr. Either way a fresh worker takes
// the remaining cases, and results land by task index, so the outcome does
// not depend on the number of workers.
#include <csignal>
#include <functional>
#include <string>
#include <vector>

#include "runner/case_result.h"

namespace snell {

struct Task {
  std::string caseId;
  std::string backend;
  double timeoutSeconds = 60;
};

struct SupervisorOptions {
  std::string executable;  // the snell binary to start workers from
  std::string shaders;
  bool validation = false;
  std::string outDir;
  std::string goldenDir;  // empty: no golden comparison
  int jobs = 1;
  // When it becomes non-zero (a signal arrived), the workers are stopped and
  // only the finished results are returned.
  const volatile std::sig_atomic_t* stop = nullptr;
  std::vector<std::string> backendArgs;  // --device, --gl-provider: passed to every worker
  std::string blessFlags;                // WorkerOptions::blessFlags
  std::string runId;                     // WorkerOptions::runId
  std::string oracleStore;               // WorkerOptions::oracleStore
};

using ResultCallback = std::function<void(std::size_t taskIndex, const CaseResult&)>;

// Returns one result per task, in task order; calls onResult as each ends.
// Stopped (options.stop), returns the finished ones only, in task order.
std::vector<CaseResult> superviseTasks(const std::vector<Task>& tasks,
                                       const SupervisorOptions& options,
                                       const ResultCallback& onResult);

}  // namespace snell
