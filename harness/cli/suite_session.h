#pragma once
// What `run` and `bless` share: read and check every manifest before any
// driver loads, then run the cases through the supervisor with progress on
// stderr, results streamed to --json as they end.
#include <CLI/CLI.hpp>
#include <map>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "baseline/baseline_judgement.h"
#include "core/case.h"
#include "runner/case_result.h"

namespace snell::cli {

struct SuiteOptions {
  // Registered names joined by commas, or all. The default is the drivers
  // whose goldens the repository keeps.
  std::string backend = "gl,vk";
  std::string device;      // --device, passed to every worker
  std::string glProvider;  // --gl-provider, passed to every worker
  std::string filter;
  std::string shaders;
  std::string golden;
  std::string out = "snell-out";
  std::string json;
  bool validation = false;
  int jobs = 0;        // 0: one per core
  double timeout = 0;  // 0: each manifest's own
  // Where the workers keep oracle results across runs: a folder, "off", or
  // empty for the default (runner/oracle_store/oracle_store.h).
  std::string oracleCache;
  // `run` only (bless leaves them empty):
  std::string expectations;  // folder or PREFIX-fails.txt
  int reruns = 0;            // reruns of an unexpected failure
  std::string shard;         // I/N
  std::string resume;        // results file of an interrupted run
};

// The backends a run asks for, each known to come up: probed in worker
// processes (runner/backend_probe.h). A named backend whose driver does not
// come up is one SetupError (exit 2), not a crash per case; `all` skips it
// with a note on stderr. `drivers`, when given, gets each one's driver.
std::vector<std::string> backendsToRun(const SuiteOptions& options,
                                       std::map<std::string, DriverInfo>* drivers = nullptr);

// --device and --gl-provider as worker arguments.
std::vector<std::string> workerBackendArgs(const SuiteOptions& options);

// The user's --shaders and --golden as typed, where they are not the
// defaults: what advice to run another command must repeat.
std::string userFolderFlags(const SuiteOptions& options);

struct SuiteRun {
  std::vector<Manifest> manifests;
  std::vector<Case> cases;
  std::vector<CaseResult> results;  // in case order, per backend
  ExpectationSet expectations;
  std::vector<SkippedCase> skipped;  // kept out of the run by a skips file
  int interruptedBy = 0;             // the signal that stopped the run, or 0
  std::size_t planned = 0;           // results the run would have given
  int workers = 0;                   // worker processes side by side
  double crossApiSeconds = 0;        // the supervisor's images across APIs
  std::string oracleStore;           // the folder of stored oracle results; empty: none
};

// The options `run` and `bless` share, with the repository's folders as defaults.
void addSuiteOptions(CLI::App& sub, SuiteOptions& options);

// `onlyImageCases`: bless runs the cases that draw. `compareGoldens`: off
// for bless. Throws UsageError for bad input.
SuiteRun runSuite(const SuiteOptions& options, bool onlyImageCases, bool compareGoldens);

}  // namespace snell::cli
