#include "cli/suite_session.h"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <exception>
#include <filesystem>
#include <future>
#include <map>
#include <optional>
#include <set>
#include <thread>

#include "backends/backend_registry.h"
#include "baseline/driver_build.h"
#include "baseline/expectation_file.h"
#include "baseline/merge_results.h"
#include "baseline/results_file.h"
#include "baseline/shard.h"
#include "cli/backend_options.h"
#include "cli/case_filter.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cli/shell_word.h"
#include "compare/image_library.h"
#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/listing_digest.h"
#include "core/message.h"
#include "core/scene_file.h"
#include "runner/backend_probe.h"
#include "runner/case_result_json.h"
#include "runner/case_runner.h"
#include "runner/case_validation.h"
#include "runner/cross_api_check.h"
#include "runner/fragment_vector_check.h"
#include "runner/interrupt_flag.h"
#include "runner/json_fields.h"
#include "runner/open_file_budget.h"
#include "runner/oracle_store/oracle_store.h"
#include "runner/supervisor.h"

namespace snell::cli {
namespace fs = std::filesystem;

std::vector<std::string> workerBackendArgs(const SuiteOptions& options) {
  std::vector<std::string> args;
  if (!options.device.empty()) args.insert(args.end(), {"--device", options.device});
  if (!options.glProvider.empty()) args.insert(args.end(), {"--gl-provider", options.glProvider});
  return args;
}

std::string userFolderFlags(const SuiteOptions& options) {
  std::string flags;
  if (options.shaders != defaultShadersDir()) flags += "--shaders " + shellWord(options.shaders);
  if (options.golden != defaultGoldenDir())
    flags += (flags.empty() ? "" : " ") + std::string("--golden ") + shellWord(options.golden);
  return flags;
}

// The backends --backend names (every one `all` takes), whether or not
// they come up here.
std::vector<std::string> wantedBackends(const SuiteOptions& options) {
  std::vector<std::string> wanted;
  if (options.backend == "all") {
    for (const BackendEntry& e : backendRegistry().entries())
      if (e.inAll) wanted.push_back(e.name);
  } else {
    for (const std::string& name : splitBackendList(options.backend))
      wanted.push_back(backendRegistry().find(name).name);
  }
  return wanted;
}

std::vector<std::string> backendsToRun(const SuiteOptions& options,
                                       std::map<std::string, DriverInfo>* drivers) {
  const bool all = options.backend == "all";
  const std::vector<std::string> wanted = wantedBackends(options);
  // Brought up as the cases' workers bring it up: a validation layer that
  // is not installed failed every case as a Crash, each saying why.
  std::vector<std::string> probeArgs = workerBackendArgs(options);
  if (options.validation) probeArgs.push_back("--validation");
  const std::vector<BackendProbe> probes =
      probeBackends(fs::read_symlink("/proc/self/exe").string(), wanted, probeArgs);
  std::vector<std::string> up;
  for (const BackendProbe& probe : probes) {
    if (probe.up) {
      up.push_back(probe.backend);
      if (drivers) (*drivers)[probe.backend] = probe.driver;
      continue;
    }
    if (!all)
      throw SetupError(
          fmt::format("backend {} cannot be brought up: {}", probe.backend, probe.problem));
    printMessage(stderr, "snell: skipping {}: {}\n", probe.backend, probe.problem);
  }
  if (up.empty()) throw SetupError("no backend comes up on this machine (`snell devices`)");
  return up;
}

namespace {

// -j, or one worker per core, fitted to the open-file limit: an asked -j
// that does not fit is refused before the run starts; the default is
// lowered, saying so.
int workersForRun(int asked) {
  const int wanted =
      asked > 0 ? asked : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  const WorkerFit fit = fitWorkersToOpenFileLimit(wanted);
  if (fit.workers == wanted) return wanted;
  const std::string limits =
      fit.hardLimit < 0 ? fmt::format("the open-file limit is {} (ulimit -n)", fit.limit)
                        : fmt::format("the open-file limit is {} (ulimit -n; hard limit {})",
                                      fit.limit, fit.hardLimit);
  if (fit.workers == 0)
    throw UsageError(fmt::format(
        "not even one worker fits: {}, and a run keeps {} open files of its own and {} per "
        "worker; raise the limit (ulimit -n 1024)",
        limits, kDescriptorsKeptForTheRun, kDescriptorsPerWorker));
  if (asked > 0)
    throw UsageError(
        fmt::format("-j {}: {}, and each worker keeps {} open; use -j {} or less, or "
                    "raise the limit",
                    asked, limits, kDescriptorsPerWorker, fit.workers));
  printMessage(stderr, "snell: {} worker{}, not one per core ({}): {}\n", fit.workers,
               fit.workers == 1 ? "" : "s", wanted, limits);
  return fit.workers;
}

// The folder of stored oracle results the workers use, made here; empty for
// none. One that cannot be made costs speed, not results: said once, and
// the oracle computes everything.
std::string oracleStoreFor(const SuiteOptions& options) {
  if (isOracleStoreOff(options.oracleCache)) return "";
  const OracleStoreFolder folder = prepareOracleStoreDir(
      options.oracleCache.empty() ? defaultOracleStoreDir() : fs::path(options.oracleCache),
      "Pass --oracle-cache DIR, or --oracle-cache off to say so");
  if (!folder.note.empty()) printMessage(stderr, "snell: {}\n", folder.note);
  return folder.dir.string();
}

// Results of an interrupted run are never overwritten unread: a
// FILE.partial left by a run that was killed is the only copy of its cases,
// and this run's --json would write over it. And --resume takes a run that
// was interrupted: a finished one has nothing to go on with, and resuming
// it would copy it, stale, over --json.
void requireNothingToResumeIsLost(const SuiteOptions& options) {
  if (!options.json.empty()) {
    const fs::path partial = options.json + kPartialSuffix;
    std::error_code error;
    const bool resumingIt =
        !options.resume.empty() && fs::equivalent(options.resume, partial, error);
    // An empty one (a run killed before its first result) has nothing to
    // lose.
    if (fs::exists(partial, error) && fs::file_size(partial, error) > 0 && !error && !resumingIt)
      throw UsageError(fmt::format(
          "{} holds the results of a run that was killed: go on with it (--resume {} --json {}), "
          "or remove it to start again",
          partial.string(), shellWord(partial.string()), shellWord(options.json)));
  }
  if (options.resume.empty() || options.resume.ends_with(kPartialSuffix)) return;
  ResultsFileState state;
  const std::vector<CaseResult> records = readResultsFile(options.resume, &state);
  // A run interrupted before its first result wrote none, and says to go
  // on with it: that is running every case.
  if (records.empty()) return;
  if (!state.incomplete && state.tornLine == 0)
    throw UsageError(fmt::format(
        "--resume {}: a finished run ({} records, none marked incomplete), so nothing to go on "
        "with; run without --resume to run it again",
        options.resume, records.size()));
}

// A run goes on on the driver build it began on: results of two builds
// under one backend would be credited to one of them.
void requireSameDriverBuild(const std::string& file, const CaseResult& r,
                            const std::map<std::string, DriverInfo>& drivers) {
  const auto here = drivers.find(r.backend);
  if (here == drivers.end() || sameDriverBuild(here->second, r.driver)) return;
  throw UsageError(fmt::format(
      "--resume {}: its {} results ran on {}, and {} here is {}: go on with them on that build, "
      "or run without --resume",
      file, r.backend, driverBuildName(r.driver), r.backend, driverBuildName(here->second)));
}

// Every result of the resumed file is one this command would give: one it
// would not (another filter, shard or backend list) would be dropped from
// --json without a word. `left` holds those no case of the run took.
void requireEveryResumedResultKept(const std::string& file,
                                   const std::map<std::string, CaseResult>& left) {
  if (left.empty()) return;
  const CaseResult& first = left.begin()->second;
  throw UsageError(fmt::format(
      "--resume {}: holds {} result{} this command does not give (one: {} on {}): go on with "
      "the command that wrote it (the same --filter, --shard, --backend and --expectations)",
      file, left.size(), left.size() == 1 ? "" : "s", first.caseId, first.backend));
}

}  // namespace

void addSuiteOptions(CLI::App& sub, SuiteOptions& options) {
  options.shaders = defaultShadersDir();
  options.golden = defaultGoldenDir();
  addBackendOptions(sub, options.backend, options.device, options.glProvider);
  sub.add_option("--filter", options.filter, "Only cases whose id matches this glob")
      ->check(nonEmptyGlob());
  sub.add_option("--shaders", options.shaders, "Folder of listings")
      ->check(CLI::ExistingDirectory)
      ->capture_default_str();
  sub.add_option("--golden", options.golden, "Folder of blessed goldens")
      ->check(nonEmptyPath())
      ->capture_default_str();
  sub.add_option("--json", options.json, "Write results as JSON Lines, one object per case")
      ->check(nonEmptyPath());
  sub.add_option("--out", options.out,
                 "Folder for rendered images, heat maps and masks (default: snell-out)")
      ->check(nonEmptyPath());
  sub.add_option("-j,--jobs", options.jobs, "Worker processes (default: one per core)")
      ->check(wholeNumber())
      ->check(CLI::Range(1, 256));
  sub.add_option("--timeout", options.timeout,
                 "Seconds a case may take before its worker is killed (default: the manifest's)")
      ->check(CLI::Range(0.001, 86400.0))  // a readable range, not "0 to DBL_MAX"
      ->check(notNan());
  sub.add_option(
         "--oracle-cache", options.oracleCache,
         "Folder where oracle results and compiled Vulkan programs are kept across "
         "runs, or off (default: $SNELL_ORACLE_CACHE, else $XDG_CACHE_HOME/snell/oracle, else "
         "~/.cache/snell/oracle)")
      ->check(nonEmptyPath());
  sub.add_flag("--validation", options.validation,
               "Vulkan: run under the Khronos validation layer; any message fails the case");
}

namespace {

// The default golden folder is the catalog's, in snell's source tree. The
// image cases of another --shaders folder (none of the catalog's has their id) keep
// their goldens in a folder of their own: blessed there by default, they
// would be written into snell's tree, and a run would fail each on a missing
// golden with advice to do so.
void requireOwnGoldenFolder(const SuiteOptions& options, const std::set<std::string>& imageCases) {
  std::error_code error;
  // The catalog itself: a listing new to it is blessed into its folder.
  if (fs::equivalent(options.shaders, defaultShadersDir(), error)) return;
  if (!fs::equivalent(options.golden, defaultGoldenDir(), error)) return;
  std::vector<std::string> own;
  for (const std::string& id : imageCases)
    if (!fs::exists(fs::path(options.golden) / id, error)) own.push_back(id);
  if (own.empty()) return;
  throw UsageError(fmt::format(
      "{} {} not among snell's catalog's cases: give --golden DIR, a folder of your own for "
      "{} goldens (the default, {}, is the catalog's, in snell's source tree)",
      fmt::join(own.begin(), own.begin() + std::min<std::size_t>(own.size(), 3), ", "),
      own.size() > 3 ? fmt::format("and {} more are", own.size() - 3)
                     : (own.size() == 1 ? "is" : "are"),
      own.size() == 1 ? "its" : "their", defaultGoldenDir()));
}

}  // namespace

SuiteRun runSuite(const SuiteOptions& options, bool onlyImageCases, bool compareGoldens) {
  requireDriverOptionsRead(splitBackendList(options.backend), options.device, options.glProvider);
  if (compareGoldens && !fs::is_directory(options.golden))
    throw UsageError(
        fmt::format("{}: {}; pass --golden DIR", options.golden,
                    fs::exists(options.golden) ? "not a folder" : "no such golden folder"));
  SuiteRun run;
  run.manifests = loadCatalog(options.shaders);
  std::vector<std::string> notImageCases;
  for (Case& c : expandCases(run.manifests, options.filter)) {
    if (!onlyImageCases || c.spec.has("image"))
      run.cases.push_back(std::move(c));
    else
      notImageCases.push_back(c.id);
  }
  if (run.cases.empty())
    throw UsageError(noCaseMatchesMessage(run.manifests, options.filter,
                                          onlyImageCases ? "image " : "", notImageCases));
  std::optional<Shard> shard;
  if (!options.shard.empty()) shard = parseShard(options.shard);
  // Validating the cases (a derived oracle parses its listing) and asking
  // worker processes whether their drivers come up take about as long each
  // and need nothing of each other: both at once. A case's own error is
  // reported before a driver's.
  std::future<void> validated =
      std::async(std::launch::async, [&] { validateCases(run.cases, options.shaders); });
  std::vector<std::string> backends;
  std::map<std::string, DriverInfo> drivers;
  std::exception_ptr backendError;
  try {
    backends = backendsToRun(options, &drivers);
  } catch (...) {
    backendError = std::current_exception();
  }
  validated.get();
  if (backendError) std::rethrow_exception(backendError);
  // The validation layer is Vulkan's: asked for on a run with no Vulkan
  // backend, it would check nothing, which is said rather than passed over.
  if (options.validation && std::none_of(backends.begin(), backends.end(), [](const auto& name) {
        return backendRegistry().find(name).family == "vk";
      }))
    printMessage(stderr,
                 "snell: note: --validation checks Vulkan backends only, and this run has none "
                 "({})\n",
                 fmt::join(backends, ", "));
  // The run's cases before the shard takes its own: each record counts every
  // shard's (below), once the skips are known.
  std::vector<std::string> runCaseIds;
  if (shard)
    for (const Case& c : run.cases) runCaseIds.push_back(c.id);
  if (shard) {
    std::vector<Case> mine;
    for (std::size_t k = 0; k < run.cases.size(); ++k)
      if (shard->contains(k)) mine.push_back(std::move(run.cases[k]));
    run.cases = std::move(mine);
  }
  if (!options.expectations.empty()) {
    run.expectations = loadExpectations(options.expectations, backends, todayUtc());
    std::vector<std::string> caseIds;
    for (const Case& c : expandCases(run.manifests, "")) caseIds.push_back(c.id);
    for (const std::string& note : entriesMatchingNoCase(run.expectations, caseIds))
      printMessage(stderr, "snell: note: {}\n", note);
  }
  requireNothingToResumeIsLost(options);
  std::map<std::string, CaseResult> resumed;
  if (!options.resume.empty())
    for (CaseResult& r : readResultsFile(options.resume)) {
      requireSameDriverBuild(options.resume, r, drivers);
      resumed[resultKey(r)] = std::move(r);
    }

  // Each record names its shard and the run it was split from (a merge
  // tells a missing shard by them); a resumed one is this command's too.
  const std::string shardLabel = shard ? fmt::format("{}/{}", shard->index, shard->count) : "";
  const std::string shardOf =
      shard ? fmt::format("--filter {} --backend {}",
                          shellWord(options.filter.empty() ? "*" : options.filter),
                          shellWord(options.backend))
            : "";
  // Counted over the backends the run asks for, not those up here: another
  // runner of the same run may have more up.
  std::vector<std::size_t> shardCases;
  if (shard) {
    const std::vector<std::string> wanted = wantedBackends(options);
    shardCases.assign(shard->count, 0);
    for (std::size_t k = 0; k < runCaseIds.size(); ++k)
      if (std::any_of(wanted.begin(), wanted.end(), [&](const std::string& backend) {
            return run.expectations.of(backend).skip(runCaseIds[k]) == nullptr;
          }))
        ++shardCases[k % shard->count];
  }
  // Each record says which listing text it ran (a merge tells a shard run
  // on another catalog by it, a resumed run an edited listing): read once
  // per listing.
  std::map<const Manifest*, std::string> digestOf;
  std::set<const Manifest*> editedDuringRun;
  for (const Case& c : run.cases)
    if (!digestOf.count(c.manifest)) digestOf[c.manifest] = listingDigest(*c.manifest);
  // One slot per result the run gives, in order: a case already finished in
  // the resumed file keeps its result; the others become tasks.
  std::vector<Task> tasks;
  std::vector<std::optional<CaseResult>> slots;
  std::vector<std::size_t> slotOfTask;
  bool resumedImages = false;
  std::set<std::string> imageCaseIds;  // of the cases that will draw
  for (const std::string& backend : backends)
    for (const Case& c : run.cases) {
      if (const CasePattern* skip = run.expectations.of(backend).skip(c.id)) {
        run.skipped.push_back({backend, c.id, skip});
        continue;
      }
      auto done = resumed.find(backend + " " + c.id);
      // A finished case that ran another text of its listing (edited since)
      // is run again: its result is not this listing's.
      if (done != resumed.end() && !done->second.listingDigest.empty() &&
          done->second.listingDigest != digestOf.at(c.manifest)) {
        if (done->second.listingDigest == kListingEditedDuringRun)
          printMessage(stderr,
                       "snell: note: {}: {} on {} ended while its listing was being edited, so "
                       "which text it ran is unknown; it runs again\n",
                       options.resume, c.id, backend);
        else
          printMessage(stderr,
                       "snell: note: {}: {} on {} ran another text of its listing, which has "
                       "been edited since; it runs again\n",
                       options.resume, c.id, backend);
        resumed.erase(done);
        done = resumed.end();
      }
      if (done != resumed.end()) {
        // Its image is compared with the other backends' after the run.
        resumedImages = resumedImages || c.spec.has("image");
        done->second.shard = shardLabel;
        done->second.shardOf = shardOf;
        done->second.shardCases = shardCases;
        slots.emplace_back(std::move(done->second));
        resumed.erase(done);
        continue;
      }
      slotOfTask.push_back(slots.size());
      slots.emplace_back();
      tasks.push_back(
          {c.id, backend, options.timeout > 0 ? options.timeout : c.manifest->timeoutSeconds});
      if (c.spec.has("image")) imageCaseIds.insert(c.id);
    }
  run.planned = slots.size();
  requireEveryResumedResultKept(options.resume, resumed);
  // Only an image case that will run, or one resumed whose image is still
  // to be compared across APIs, needs the image module: one the shard or a
  // skip list leaves out does not, so a machine without OpenImageIO can run
  // the vector cases by skipping the image ones.
  const bool drawsImages = !imageCaseIds.empty();
  if (drawsImages || resumedImages) requireImageLibraryFile();
  requireOwnGoldenFolder(options, imageCaseIds);

  const int workers = workersForRun(options.jobs);

  fs::create_directories(options.out);
  std::unique_ptr<StreamingFile> json;
  if (!options.json.empty()) json = std::make_unique<StreamingFile>(options.json);
  for (const auto& slot : slots)
    if (slot && json) json->writeLine(jsonText(toJson(*slot)));
  const InterruptFlag interrupt;
  SupervisorOptions supervisor;
  supervisor.executable = fs::read_symlink("/proc/self/exe").string();
  supervisor.shaders = fs::absolute(options.shaders).string();
  supervisor.validation = options.validation;
  supervisor.backendArgs = workerBackendArgs(options);
  supervisor.blessFlags = userFolderFlags(options);
  // Unique to this run: its workers share the CPU reference images they
  // render, and never take one left in --out by an earlier run.
  supervisor.runId =
      fmt::format("{}-{}", ::getpid(), std::chrono::system_clock::now().time_since_epoch().count());
  supervisor.outDir = fs::absolute(options.out).string();
  supervisor.goldenDir = compareGoldens ? fs::absolute(options.golden).string() : "";
  supervisor.jobs = workers;
  supervisor.stop = interrupt.flag();
  run.oracleStore = oracleStoreFor(options);
  supervisor.oracleStore = run.oracleStore;
  run.workers = supervisor.jobs;
  // The images across APIs are compared here once the workers are done; the
  // image module (a third of a second of loading) opens meanwhile, so that
  // comparison does not wait for it. A module that does not open is said
  // by that comparison, which asks again. With an oracle store, a run on
  // the images of an earlier one compares nothing anew and needs no module:
  // it opens once a case says it computed an oracle result, the sign of
  // new work.
  std::future<void> imagesReady;
  const auto openImagesMeanwhile = [&] {
    if (!drawsImages || imagesReady.valid()) return;
    imagesReady = std::async(std::launch::async, [] {
      try {
        imageLibrary();
      } catch (const SetupError&) {
      }
    });
  };
  if (run.oracleStore.empty()) openImagesMeanwhile();
  std::size_t finished = slots.size() - tasks.size();
  std::map<std::string, const Case*> caseById;
  for (const Case& c : run.cases) caseById[c.id] = &c;
  // The listing read again as a case (or its rerun) ends: a text edited
  // since the run began may be the one the case compiled, or not, and the
  // record says so in place of a digest (the returned flag).
  const auto markIfEdited = [&](CaseResult& result, const Manifest* listing) {
    if (result.listingDigest == kListingEditedDuringRun) return true;
    if (listingDigest(*listing) == digestOf.at(listing)) return false;
    result.listingDigest = kListingEditedDuringRun;
    if (editedDuringRun.insert(listing).second)
      printMessage(stderr,
                   "snell: note: {} was edited while this run was in progress; which text "
                   "its cases from here on compiled is unknown, so their records say so, "
                   "and `run --resume` runs them again\n",
                   listing->path.string());
    return true;
  };

  superviseTasks(tasks, supervisor, [&](std::size_t task, const CaseResult& finishedCase) {
    ++finished;
    CaseResult result = finishedCase;
    // A case whose worker was lost (a timeout, a crash) comes back with its
    // id alone: what the catalog and the driver probe know is filled in,
    // and its time is charged to Other, so its phases add up to it.
    if (result.title.empty())
      if (const auto c = caseById.find(result.caseId); c != caseById.end()) {
        result.title = c->second->manifest->title;
        result.sourceFile = c->second->manifest->source.file;
        result.sourceWhere = c->second->manifest->source.where;
      }
    if (result.driver.renderer.empty())
      if (const auto d = drivers.find(result.backend); d != drivers.end())
        result.driver = d->second;
    if (result.phases.total() == 0.0) result.phases[Phase::Other] = result.seconds;
    result.shard = shardLabel;
    result.shardOf = shardOf;
    result.shardCases = shardCases;
    if (const auto c = caseById.find(result.caseId); c != caseById.end()) {
      result.listingDigest = digestOf.at(c->second->manifest);
      markIfEdited(result, c->second->manifest);
    }
    printMessage(stderr, "[{}/{}] {} {} {} ({:.2f}s)\n", finished, slots.size(), result.backend,
                 result.caseId, statusName(result.status), result.seconds);
    if (json) json->writeLine(jsonText(toJson(result)));
    if (result.oracleResults > result.oracleStored) openImagesMeanwhile();
    slots[slotOfTask[task]] = std::move(result);
  });
  for (auto& slot : slots)
    if (slot) run.results.push_back(std::move(*slot));
  run.interruptedBy = interrupt.signal();

  // An unexpected failure runs again: one that then passes is a flake.
  for (int round = 0; round < options.reruns && !run.interruptedBy; ++round) {
    std::vector<CaseResult*> again;
    std::vector<Task> rerunTasks;
    for (CaseResult& r : run.results)
      if (isUnexpectedFailure(run.expectations, r) &&
          std::all_of(r.reruns.begin(), r.reruns.end(), isFailure)) {
        again.push_back(&r);
        const Case& c = *std::find_if(run.cases.begin(), run.cases.end(),
                                      [&](const Case& x) { return x.id == r.caseId; });
        rerunTasks.push_back({r.caseId, r.backend,
                              options.timeout > 0 ? options.timeout : c.manifest->timeoutSeconds});
      }
    if (again.empty()) break;
    superviseTasks(rerunTasks, supervisor, [&](std::size_t task, const CaseResult& result) {
      printMessage(stderr, "[rerun {}] {} {} {} ({:.2f}s)\n", round + 1, result.backend,
                   result.caseId, statusName(result.status), result.seconds);
      // A rerun of an edited listing is not counted: its pass would make
      // a failure of the other text a flake, which the gate lets through.
      if (const auto c = caseById.find(result.caseId);
          c != caseById.end() && markIfEdited(*again[task], c->second->manifest)) {
        printMessage(stderr,
                     "snell: note: the rerun of {} on {} is not counted: its listing was "
                     "edited during the run\n",
                     result.caseId, result.backend);
        return;
      }
      again[task]->reruns.push_back(result.status);
    });
    run.interruptedBy = interrupt.signal();
  }
  if (imagesReady.valid()) imagesReady.wait();
  const auto crossApiStart = std::chrono::steady_clock::now();
  const std::optional<OracleStore> store =
      run.oracleStore.empty() ? std::nullopt
                              : std::optional<OracleStore>(OracleStore(run.oracleStore));
  checkAcrossApis(run.cases, options.out, run.results, store ? &*store : nullptr);
  run.crossApiSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - crossApiStart).count();
  // The streamed file is in completion order; the kept one is in task order,
  // so it is the same whatever the number of workers.
  if (json) json->finish(toResultsJsonLines(run.results, run.interruptedBy != 0));
  if (!run.oracleStore.empty()) trimKeyedFileStore(run.oracleStore, kOracleStoreMaxBytes);
  return run;
}

}  // namespace snell::cli
