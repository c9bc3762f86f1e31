#include "cli/suite_session.h"

#include "cli/commands.h"

#include <fmt/format.h>

#include <filesystem>
#include <thread>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/scene_file.h"
#include "runner/case_result_json.h"
#include "runner/case_runner.h"
#include "runner/case_validation.h"
#include "runner/cross_api_check.h"
#include "runner/fragment_vector_check.h"
#include "runner/supervisor.h"

namespace snell::cli {
namespace fs = std::filesystem;

void addSuiteOptions(CLI::App& sub, SuiteOptions& options) {
  options.shaders = defaultShadersDir();
  options.golden = defaultGoldenDir();
  sub.add_option("--backend", options.backend, "gl, vk or all")
      ->check(CLI::IsMember({"gl", "vk", "all"}));
  sub.add_option("--filter", options.filter, "Only cases whose id matches this glob");
  sub.add_option("--shaders", options.shaders, "Folder of listings")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  sub.add_option("--golden", options.golden, "Folder of blessed goldens")->capture_default_str();
  sub.add_option("--json", options.json, "Write results as JSON Lines, one object per case");
  sub.add_option("--out", options.out,
                  "Folder for rendered images, heat maps and masks (default: snell-out)");
  sub.add_option("-j,--jobs", options.jobs, "Worker processes (default: one per core)")
      ->check(CLI::Range(1, 256));
  sub.add_option("--timeout", options.timeout,
                  "Seconds a case may take before its worker is killed (default: the manifest's)")
      ->check(CLI::Range(0.001, 86400.0));  // a readable range, not "0 to DBL_MAX"
  sub.add_flag("--validation", options.validation,
                "Vulkan: run under the Khronos validation layer; any message fails the case");
}

SuiteRun runSuite(const SuiteOptions& options, bool onlyImageCases, bool compareGoldens) {
  if (compareGoldens && !fs::is_directory(options.golden))
    throw UsageError(fmt::format("{}: no such golden folder; pass --golden DIR", options.golden));
  SuiteRun run;
  run.manifests = loadManifests(options.shaders);
  for (Case& c : expandCases(run.manifests, options.filter))
    if (!onlyImageCases || c.spec.has("image")) run.cases.push_back(std::move(c));
  if (run.cases.empty())
    throw UsageError(fmt::format("no {}case matches --filter '{}'; `snell list` shows the ids",
                                 onlyImageCases ? "image " : "", options.filter));
  validateCases(run.cases, options.shaders);

  const std::vector<std::string> backends =
      options.backend == "all" ? std::vector<std::string>{"gl", "vk"}
                               : std::vector<std::string>{options.backend};
  std::vector<Task> tasks;
  for (const std::string& backend : backends)
    for (const Case& c : run.cases)
      tasks.push_back({c.id, backend, options.timeout > 0 ? options.timeout : c.manifest->timeoutSeconds});

  fs::create_directories(options.out);
  std::unique_ptr<StreamingFile> json;
  if (!options.json.empty()) json = std::make_unique<StreamingFile>(options.json);
  SupervisorOptions supervisor;
  supervisor.executable = fs::read_symlink("/proc/self/exe").string();
  supervisor.shaders = fs::absolute(options.shaders).string();
  supervisor.validation = options.validation;
  supervisor.outDir = fs::absolute(options.out).string();
  supervisor.goldenDir = compareGoldens ? fs::absolute(options.golden).string() : "";
  supervisor.jobs = options.jobs > 0
                        ? options.jobs
                        : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  std::size_t finished = 0;
  run.results = superviseTasks(tasks, supervisor, [&](std::size_t, const CaseResult& result) {
    ++finished;
    fmt::print(stderr, "[{}/{}] {} {} {} ({:.2f}s)\n", finished, tasks.size(), result.backend,
               result.caseId, statusName(result.status), result.seconds);
    if (json) json->writeLine(toJson(result).dump());
  });
  checkAcrossApis(run.cases, options.out, run.results);
  // The streamed file is in completion order; the kept one is in task order,
  // so it is the same whatever the number of workers.
  if (json) {
    std::string ordered;
    for (const CaseResult& r : run.results) ordered += toJson(r).dump() + "\n";
    json->finish(ordered);
  }
  return run;
}

}  // namespace snell::cli
