#pragma once
// What `run` and `bless` share: read and check every manifest before any
// driver loads, then run the cases through the supervisor with progress on
// stderr, results streamed to --json as they end.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "core/case.h"
#include "runner/case_result.h"

namespace snell::cli {

struct SuiteOptions {
  std::string backend = "all";
  std::string filter;
  std::string shaders;
  std::string golden;
  std::string out = "snell-out";
  std::string json;
  bool validation = false;
  int jobs = 0;        // 0: one per core
  double timeout = 0;  // 0: each manifest's own
};

struct SuiteRun {
  std::vector<Manifest> manifests;
  std::vector<Case> cases;
  std::vector<CaseResult> results;  // in case order, per backend
};

// The options `run` and `bless` share, with the repository's folders as defaults.
void addSuiteOptions(CLI::App& sub, SuiteOptions& options);

// `onlyImageCases`: bless runs the cases that draw. `compareGoldens`: off
// for bless. Throws UsageError for bad input.
SuiteRun runSuite(const SuiteOptions& options, bool onlyImageCases, bool compareGoldens);

}  // namespace snell::cli
