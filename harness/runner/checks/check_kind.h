#pragma once
// A kind of check a manifest names in a case's `checks` ("vectors",
// "image"): everything about it in one place, so that a new kind is its own
// files and one line in check_registry.cpp. The case runner, case
// validation, the results file, the summary table and the JUnit file go
// through this interface and know no kind by name.
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "backends/backend.h"
#include "core/case.h"
#include "runner/case_result.h"

namespace snell {

class OracleCache;
class SceneCache;
class ReferenceCache;
struct ImageCheckOptions;

// What a running check may use: the one backend of the worker and the
// caches shared by every case it runs.
struct CheckEnvironment {
  Backend& backend;
  const DriverInfo& driver;
  OracleCache& oracles;
  SceneCache& scenes;
  ReferenceCache& references;
  const ImageCheckOptions& imageOptions;
};

// A column of the summary table.
struct SummaryColumn {
  std::string header;
  int width;
  std::string (*cell)(const CaseResult&);
};

class CheckKind {
 public:
  virtual ~CheckKind() = default;
  // As manifests write it in `checks`.
  virtual std::string name() const = 0;
  // Throws UsageError "FILE:LINE: ..." for what this kind cannot run on the
  // case; called by the one validation step, before any driver loads.
  virtual void validate(const Case& c, const ProgramSource& program, const Scene& scene) const = 0;
  // Runs on one backend: adds its data to `result`, worsens its status and
  // appends to its message. A compile error ends the case (Status::CompileError).
  virtual void run(const Case& c, const ResolvedBindings& bindings, CheckEnvironment& environment,
                   CaseResult& result) const = 0;
  // Its fields of a result record, and back (throws nlohmann::json::exception).
  virtual void writeJson(const CaseResult& result, nlohmann::json& record) const = 0;
  virtual void readJson(const nlohmann::json& record, CaseResult& result) const = 0;
  virtual std::vector<SummaryColumn> summaryColumns() const = 0;
  // One line on what it found wrong, for a JUnit failure's message; empty
  // when it found nothing wrong.
  virtual std::string junitMessage(const CaseResult& result) const = 0;
};

// Every registered kind, in the order their columns and messages appear.
const std::vector<std::unique_ptr<CheckKind>>& checkKinds();

// nullptr for a name no kind has.
const CheckKind* findCheckKind(const std::string& name);

// Throws UsageError "MANIFEST:LINE: check `x` is not known; did you mean ...".
void requireKnownChecks(const Case& c);

}  // namespace snell
