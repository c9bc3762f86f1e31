#include "cli/suite_session.h"

#include "cli/backend_options.h"
#include "cli/commands.h"

#include <fmt/format.h>

#include <filesystem>
#include <thread>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/manifest_check.h"
#include "core/scene_file.h"
#include "oracle/reference/reference_image.h"
#include "oracle/vertex_oracle.h"
#include "runner/case_result_json.h"
#include "runner/case_runner.h"
#include "runner/cross_api_check.h"
#include "runner/fragment_vector_check.h"
#include "runner/backend_probe.h"
#include "runner/supervisor.h"
#include "backends/backend_registry.h"

namespace snell::cli {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void atLine(const Manifest& m, int line, const std::string& what) {
  throw UsageError(fmt::format("{}:{}: {}", m.path.string(), line, what));
}

// Everything a case needs is read before any driver is loaded, so a broken
// manifest or a missing stage file stops the run with exit 2 up front.
void validateCases(const std::vector<Case>& cases, const std::string& shaders) {
  SceneCache scenes(sceneSearchPath(shaders));
  for (const Case& c : cases) {
    const Manifest& m = *c.manifest;
    const ProgramSource program = loadProgram(m);
    const Scene* scene = nullptr;
    try {
      scene = &scenes.get(c.spec.scene);
    } catch (const UsageError& error) {
      atLine(m, c.spec.line, error.what());
    }
    const ResolvedBindings bindings = resolveBindings(m, *scene);
    checkManifestAgainstProgram(m, program, bindings);
    try {
      makeVertexOracle(m.oracle);
    } catch (const UsageError& error) {
      atLine(m, m.oracleLine, error.what());
    }
    if (c.spec.has("vectors")) {
      try {
        checkFragmentCaptures(m, program, *scene);
      } catch (const UsageError& error) {
        // Errors about the program or the oracle carry their own place.
        const std::string what = error.what();
        if (what.rfind(m.path.string() + ":", 0) == 0 || what.rfind(program.fragmentPath + ":", 0) == 0)
          throw;
        atLine(m, c.spec.line, what);
      }
    }
    if (c.spec.has("image")) {
      if (!scene->draws())
        atLine(m, c.spec.line, fmt::format("scene `{}` draws nothing; its cases check "
                                           "[\"vectors\"] only", scene->name));
      if (!hasFragmentOracle(m.oracle))
        atLine(m, m.oracleLine, fmt::format("oracle `{}` has no fragment part, so the "
                                            "\"image\" check has no reference", m.oracle));
    }
  }
}

}  // namespace

std::vector<std::string> workerBackendArgs(const SuiteOptions& options) {
  std::vector<std::string> args;
  if (!options.device.empty()) args.insert(args.end(), {"--device", options.device});
  if (!options.glProvider.empty()) args.insert(args.end(), {"--gl-provider", options.glProvider});
  return args;
}

std::vector<std::string> backendsToRun(const SuiteOptions& options) {
  const bool all = options.backend == "all";
  std::vector<std::string> wanted;
  if (all) {
    for (const BackendEntry& e : backendRegistry().entries())
      if (e.inAll) wanted.push_back(e.name);
  } else {
    for (const std::string& name : splitBackendList(options.backend))
      wanted.push_back(backendRegistry().find(name).name);
  }
  const std::vector<BackendProbe> probes =
      probeBackends(fs::read_symlink("/proc/self/exe").string(), wanted, workerBackendArgs(options));
  std::vector<std::string> up;
  for (const BackendProbe& probe : probes) {
    if (probe.up) {
      up.push_back(probe.backend);
      continue;
    }
    if (!all)
      throw SetupError(fmt::format("backend {} cannot be brought up: {}", probe.backend,
                                   probe.problem));
    fmt::print(stderr, "snell: skipping {}: {}\n", probe.backend, probe.problem);
  }
  if (up.empty()) throw SetupError("no backend comes up on this machine (`snell devices`)");
  return up;
}

void addSuiteOptions(CLI::App& sub, SuiteOptions& options) {
  options.shaders = defaultShadersDir();
  options.golden = defaultGoldenDir();
  addBackendOptions(sub, options.backend, options.device, options.glProvider);
  sub.add_option("--filter", options.filter, "Only cases whose id matches this glob");
  sub.add_option("--shaders", options.shaders, "Folder of listings")->check(CLI::ExistingDirectory);
  sub.add_option("--golden", options.golden, "Folder of blessed goldens");
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

  const std::vector<std::string> backends = backendsToRun(options);
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
  supervisor.backendArgs = workerBackendArgs(options);
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
