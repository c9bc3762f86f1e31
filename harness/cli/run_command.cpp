#include <fmt/format.h>

#include <filesystem>
#include <iostream>
#include <thread>

#include "backends/backend.h"
#include "cli/commands.h"
#include "core/case.h"
#include "core/errors.h"
#include "core/manifest_check.h"
#include "report/atomic_file.h"
#include "runner/case_result_json.h"
#include "report/junit.h"
#include "report/summary_table.h"
#include "runner/case_runner.h"
#include "runner/supervisor.h"

namespace snell::cli {
namespace {

struct RunOptions {
  std::string backend = "all";
  std::string filter;
  std::string shaders = defaultShadersDir();
  std::string golden = defaultGoldenDir();
  std::string json;
  std::string junit;
  bool validation = false;
  int jobs = 0;           // 0: one per core
  double timeout = 0;     // 0: each manifest's own
};

// Everything a case needs is read before any driver is loaded, so a broken
// manifest or a missing stage file stops the run with exit 2 up front.
void validateCases(const std::vector<Case>& cases, SceneCache& scenes) {
  for (const Case& c : cases) {
    const ProgramSource program = loadProgram(*c.manifest);
    const Scene* scene = nullptr;
    try {
      scene = &scenes.get(c.spec.scene);
    } catch (const UsageError& error) {
      throw UsageError(fmt::format("{}:{}: {}", c.manifest->path.string(), c.spec.line, error.what()));
    }
    const ResolvedBindings bindings = resolveBindings(*c.manifest, *scene);
    checkManifestAgainstProgram(*c.manifest, program, bindings);
    try {
      makeVertexOracle(c.manifest->oracle);
    } catch (const UsageError& error) {
      throw UsageError(fmt::format("{}:{}: {}", c.manifest->path.string(), c.manifest->oracleLine,
                                   error.what()));
    }
  }
}

void printThroughput(const std::vector<CaseResult>& results) {
  std::map<std::string, std::pair<std::size_t, double>> perBackend;  // vectors, seconds
  std::map<std::string, double> worst;
  for (const CaseResult& r : results) {
    perBackend[r.backend].first += r.vectorsChecked();
    perBackend[r.backend].second += r.backendSeconds;
    worst[r.backend] = std::max(worst[r.backend], r.worstSlack());
  }
  for (const auto& [backend, totals] : perBackend)
    fmt::print("{}: {} vectors checked, {:.0f} per second of backend time (compile, draw, read back), "
               "worst slack {:.3f}\n",
               backend, totals.first, totals.second > 0 ? totals.first / totals.second : 0.0,
               worst[backend]);
}

int run(const RunOptions& options) {
  if (!std::filesystem::is_directory(options.golden))
    throw UsageError(fmt::format("{}: no such golden folder; pass --golden DIR", options.golden));
  const std::vector<Manifest> manifests = loadManifests(options.shaders);
  const std::vector<Case> cases = expandCases(manifests, options.filter);
  if (cases.empty())
    throw UsageError(fmt::format("no case matches --filter '{}'; `snell list` shows the ids",
                                 options.filter));
  SceneCache scenes;
  validateCases(cases, scenes);


  const std::vector<std::string> backends =
      options.backend == "all" ? std::vector<std::string>{"gl", "vk"}
                               : std::vector<std::string>{options.backend};
  std::vector<Task> tasks;
  for (const std::string& backend : backends)
    for (const Case& c : cases)
      tasks.push_back({c.id, backend, options.timeout > 0 ? options.timeout : c.manifest->timeoutSeconds});

  std::unique_ptr<StreamingFile> json;
  if (!options.json.empty()) json = std::make_unique<StreamingFile>(options.json);
  SupervisorOptions supervisor;
  supervisor.executable = std::filesystem::read_symlink("/proc/self/exe").string();
  supervisor.shaders = std::filesystem::absolute(options.shaders).string();
  supervisor.validation = options.validation;
  supervisor.jobs = options.jobs > 0 ? options.jobs
                                     : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::size_t finished = 0;
  const std::vector<CaseResult> results = superviseTasks(
      tasks, supervisor, [&](std::size_t, const CaseResult& result) {
        ++finished;
        fmt::print(stderr, "[{}/{}] {} {} {} ({:.2f}s)\n", finished, tasks.size(), result.backend,
                   result.caseId, statusName(result.status), result.seconds);
        if (json) json->writeLine(toJson(result).dump());
      });
  // The streamed file is in completion order; the kept one is in task order,
  // so it is the same whatever the number of workers.
  if (json) {
    std::string ordered;
    for (const CaseResult& r : results) ordered += toJson(r).dump() + "\n";
    json->finish(ordered);
  }
  if (!options.junit.empty()) writeFileAtomically(options.junit, toJUnitXml(results));

  printSummaryTable(std::cout, results);
  printThroughput(results);
  bool failed = false;
  for (const CaseResult& r : results) {
    if (!isFailure(r.status)) continue;
    failed = true;
    fmt::print("\n{} on {}: {}\n{}", r.caseId, r.backend, statusName(r.status), r.message);
  }
  return failed ? 1 : 0;
}

}  // namespace

Command addRunCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand("run", "Run the conformance cases and gate on the results");
  auto options = std::make_shared<RunOptions>();
  sub->add_option("--backend", options->backend, "gl, vk or all")
      ->check(CLI::IsMember({"gl", "vk", "all"}));
  sub->add_option("--filter", options->filter, "Only cases whose id matches this glob");
  sub->add_option("--shaders", options->shaders, "Folder of listings")->check(CLI::ExistingDirectory);
  sub->add_option("--golden", options->golden, "Folder of blessed goldens");
  sub->add_option("--json", options->json, "Write results as JSON Lines, one object per case");
  sub->add_option("--junit", options->junit, "Write results as JUnit XML");
  sub->add_option("-j,--jobs", options->jobs, "Worker processes (default: one per core)")
      ->check(CLI::Range(1, 256));
  sub->add_option("--timeout", options->timeout,
                  "Seconds a case may take before its worker is killed (default: the manifest's)")
      ->check(CLI::PositiveNumber);
  sub->add_flag("--validation", options->validation,
                "Vulkan: run under the Khronos validation layer; any message fails the case");
  return [options] { return run(*options); };
}

}  // namespace snell::cli
