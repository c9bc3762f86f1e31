#include "runner/worker.h"

#include <fmt/format.h>

#include <chrono>
#include <iostream>
#include <map>
#include <nlohmann/json.hpp>
#include <utility>

#include "backends/backend.h"
#include "backends/backend_registry.h"
#include "core/case.h"
#include "core/errors.h"
#include "core/scene_file.h"
#include "runner/case_result_json.h"
#include "runner/case_runner.h"
#include "runner/case_validation.h"
#include "runner/json_fields.h"

namespace snell {

namespace {
BackendOptions backendOptions(const WorkerOptions& options) {
  return {.validation = options.validation,
          .device = options.device,
          .glProvider = options.glProvider,
          .cacheDir = options.oracleStore};
}
}  // namespace

nlohmann::json driverJson(const DriverInfo& d) {
  return {{"api", d.api},
          {"api_version", d.apiVersion},
          {"renderer", d.renderer},
          {"driver_version", d.driverVersion},
          {"device_type", d.deviceType}};
}

int runWorker(const WorkerOptions& options) {
  const BackendEntry& entry = backendRegistry().find(options.backend);
  if (options.describe) {
    const std::unique_ptr<Backend> backend = makeBackend(entry.name, backendOptions(options));
    std::cout << jsonText(driverJson(backend->driverInfo())) << std::endl;
    return 0;
  }
  const std::vector<Manifest> manifests = loadManifests(options.shaders);
  const std::vector<Case> cases = expandCases(manifests, "");
  std::map<std::string, const Case*> byId;
  for (const Case& c : cases) byId[c.id] = &c;

  std::unique_ptr<Backend> backend;  // loaded on the first case, not before
  const std::optional<OracleStore> store =
      options.oracleStore.empty() ? std::nullopt
                                  : std::optional<OracleStore>(OracleStore(options.oracleStore));
  OracleCache oracles(store);
  SceneCache scenes(sceneSearchPath(options.shaders));
  ReferenceCache references = options.runId.empty()
                                  ? ReferenceCache()
                                  : ReferenceCache(options.outDir, options.runId, store);
  std::unique_ptr<CaseRunner> runner;
  double startSeconds = 0;  // charged to the first case
  for (std::string id; std::getline(std::cin, id);) {
    auto it = byId.find(id);
    if (it == byId.end()) throw UsageError(fmt::format("worker: no case `{}`", id));
    validateCase(*it->second, scenes);  // the same step the supervisor ran
    if (!backend) {
      backend = makeBackend(entry.name, backendOptions(options));
      runner = std::make_unique<CaseRunner>(
          *backend, oracles, scenes, references,
          ImageCheckOptions{options.outDir, options.goldenDir, entry.goldenKey, options.blessFlags,
                            store});
      if (options.spawnedAtNs > 0)
        startSeconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch() -
                                          std::chrono::nanoseconds(options.spawnedAtNs))
                .count();
    }
    CaseResult result = runner->run(*it->second);
    result.phases[Phase::Start] = std::exchange(startSeconds, 0.0);
    std::cout << jsonText(toJson(result)) << std::endl;  // endl: flush per case
  }
  return 0;
}

}  // namespace snell
