#pragma once
// Runs one case on one backend: bind the scene's values, capture the
// listing's outputs, hold them against the oracle. The oracle's answer does
// not depend on the backend, so it is computed once per case and shared.
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <vector>

#include "backends/backend.h"
#include "core/case.h"
#include "oracle/vertex_oracle.h"
#include "runner/case_result.h"
#include "runner/image_check.h"
#include "runner/listing_oracles.h"
#include "runner/oracle_cache.h"

namespace snell {

class SceneCache {
 public:
  // The repository's scenes, or those on `searchPath` (core/scene_file.h).
  SceneCache();
  explicit SceneCache(std::vector<std::filesystem::path> searchPath)
      : searchPath_(std::move(searchPath)) {}
  const Scene& get(const std::string& name);

 private:
  std::vector<std::filesystem::path> searchPath_;
  std::map<std::string, Scene> scenes_;
};

class CaseRunner {
 public:
  CaseRunner(Backend& backend, OracleCache& oracles, SceneCache& scenes, ReferenceCache& references,
             ImageCheckOptions imageOptions)
      : backend_(backend),
        oracles_(oracles),
        scenes_(scenes),
        references_(references),
        imageOptions_(std::move(imageOptions)),
        driver_(backend.driverInfo()) {}

  // Never throws for what a driver does; UsageError for a broken manifest.
  CaseResult run(const Case& c);

 private:
  CaseResult runChecks(const Case& c);
  void runExpectedCompileError(const Case& c, CaseResult& result);

  Backend& backend_;
  OracleCache& oracles_;
  SceneCache& scenes_;
  ReferenceCache& references_;
  ImageCheckOptions imageOptions_;
  DriverInfo driver_;
};

}  // namespace snell
