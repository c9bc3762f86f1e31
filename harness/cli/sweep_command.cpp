#include <fmt/format.h>
#include <fmt/ranges.h>
#include <fnmatch.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <system_error>

#include "cli/backend_options.h"
#include "cli/commands.h"
#include "cli/option_checks.h"
#include "cli/output_paths.h"
#include "core/errors.h"
#include "core/manifest.h"
#include "core/message.h"
#include "runner/backend_probe.h"
#include "runner/builtin_eval.h"
#include "runner/interrupt_flag.h"
#include "sweep/listing_capture.h"
#include "sweep/listing_draw.h"
#include "sweep/sweep_charts.h"
#include "sweep/sweep_report.h"
#include "sweep/sweep_run.h"

namespace snell::cli {
namespace {

namespace fs = std::filesystem;

// --json on a file that the sweep writes or removes in --out (its input, a
// driver's batch, the listings' job file, a chart, gnuplot's script or log)
// was overwritten, or removed as an earlier sweep's chart, with exit 0; in
// the charts' data folder it was removed with the folder. Refused by name,
// whether or not such a file is there yet.
void refuseJsonOnOwnFiles(const fs::path& json, const fs::path& out) {
  const fs::path folder = fs::absolute(json).parent_path();
  const std::string role = sweep::ownFileRole(json.filename().string());
  if (!role.empty() && isAtOrWithin(folder, out) && isAtOrWithin(out, folder))
    throw UsageError(fmt::format(
        "--json {}: in --out {}, a file of this name is the sweep's own ({}), which it writes "
        "or removes; name a file of another name, or one elsewhere",
        json.string(), out.string(), role));
  if (isAtOrWithin(json, out / sweep::kChartDataFolder))
    throw UsageError(fmt::format(
        "--json {}: inside {}, the charts' own folder, which every sweep replaces; name a "
        "file elsewhere",
        json.string(), (out / sweep::kChartDataFolder).string()));
}

}  // namespace

Command addSweepCommand(CLI::App& app) {
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Sweep refract(), reflect() and the catalog's listings over incidence angle, eta and bad "
      "inputs on the oracle and each driver, and the Fresnel methods against exact Fresnel; "
      "classify every break");
  struct Options {
    std::string backend = "gl,vk";
    std::string out = "snell-out/sweep";
    std::string json;
    bool quick = false;
    bool noCharts = false;
    double timeout = 300;
    std::string device;
    std::string glProvider;
    std::string listings = "*";
    bool noBuiltins = false;
    std::string shaders = defaultShadersDir();
    std::string listingWorker;
    std::size_t listingStart = 0;
  };
  auto options = std::make_shared<Options>();
  sweep
      ->add_option("--backend", options->backend,
                   "Drivers to sweep, joined by commas (`snell devices`); the oracle is always "
                   "swept")
      ->check([](const std::string& value) { return backendListReason(value, false); })
      ->capture_default_str();
  addDriverOptions(*sweep, options->device, options->glProvider);
  sweep
      ->add_option("--listings", options->listings,
                   "Catalog listings to sweep (glob over ids, `snell list`); empty: none")
      ->capture_default_str();
  sweep->add_option("--shaders", options->shaders, "The catalog's folder")->capture_default_str();
  sweep->add_flag("--no-builtins", options->noBuiltins,
                  "Skip refract() and reflect() themselves (the listings only)");
  // The driver child of the listings' sweep (listing_capture.h): not for people.
  sweep->add_option("--listing-worker", options->listingWorker)->group("");
  sweep->add_option("--listing-start", options->listingStart)->group("");
  sweep->add_option("--out", options->out, "Folder for the charts, their data and the input")
      ->capture_default_str()
      ->check(nonEmptyPath());
  sweep->add_option("--json", options->json, "Breaks as JSON (default OUT/sweep.json)")
      ->check(nonEmptyPath());
  sweep->add_flag("--quick", options->quick, "A few etas and angles (for tests)");
  sweep->add_flag("--no-charts", options->noCharts,
                  "Skip the gnuplot charts (an earlier sweep's in --out are removed when "
                  "sweep.json is written there)");
  sweep->add_option("--timeout", options->timeout, "Seconds each driver may take")
      ->check(CLI::Range(0.001, 86400.0))  // a readable range, not "0 to DBL_MAX"
      ->check(notNan())
      ->capture_default_str();
  sweep->footer(
      "Each break is implementation (a backend left its spec interval, or crashed), undefined\n"
      "(the spec allows anything there) or method (a Fresnel method past its error bound\n"
      "against exact Fresnel, or outside its physical range). The catalog's listings are drawn\n"
      "at the sweep's points on each driver (--listings). Exit 1 when an implementation\n"
      "break was found; 2, before anything is swept, when none of the listings --listings\n"
      "names (or, with --no-builtins, no listing at all) can be swept, each with its reason.");
  return [options, sweep] {
    if (!options->listingWorker.empty()) {
      BackendOptions backendOptions;
      backendOptions.device = options->device;
      backendOptions.glProvider = options->glProvider;
      return sweep::runListingWorker(options->listingWorker, options->listingStart,
                                     options->backend, backendOptions);
    }
    requireDriverOptionsRead(splitBackendList(options->backend), options->device,
                             options->glProvider);
    // A --shaders folder with no listings, or a --listings glob that matches
    // none, is refused before the built-ins' sweep, not found empty after it.
    if (options->noBuiltins && options->listings.empty())
      throw UsageError(
          "nothing to sweep: --no-builtins with --listings '' leaves no built-in and "
          "no listing; name listings with --listings GLOB");
    // Listings named with --listings of which none can be swept, or, with
    // --no-builtins, no listing that can be: exit 0 would vouch for what was
    // not checked, and whether a listing can be swept is known from its
    // manifest, so it is refused here, before the minute of the built-ins.
    const bool listingsNamed = sweep->count("--listings") > 0;
    if (!options->listings.empty()) {
      const std::vector<Manifest> catalog = loadCatalog(options->shaders);
      std::vector<std::string> unsweepable;
      bool matched = false, sweepable = false;
      for (const Manifest& m : catalog) {
        if (fnmatch(options->listings.c_str(), m.id.c_str(), 0) != 0) continue;
        matched = true;
        if (const std::string why = sweep::whyNotSwept(m); !why.empty())
          unsweepable.push_back(m.id + ": " + why);
        else
          sweepable = true;
      }
      if (!matched)
        throw UsageError(
            fmt::format("no listing matches --listings '{}'; `snell list` shows the "
                        "ids (a listing's id is its cases' ids without the scene)",
                        options->listings));
      if (!sweepable && (listingsNamed || options->noBuiltins))
        throw UsageError(fmt::format(
            "{}: {}",
            listingsNamed
                ? fmt::format("no listing that --listings '{}' names can be swept",
                              options->listings)
                : "nothing to sweep: --no-builtins leaves the listings, and none of them can be",
            fmt::join(unsweepable, "; ")));
    }
    const auto start = std::chrono::steady_clock::now();
    const std::string executable = fs::read_symlink("/proc/self/exe").string();
    std::vector<std::string> driverArgs;
    if (!options->device.empty())
      driverArgs.insert(driverArgs.end(), {"--device", options->device});
    if (!options->glProvider.empty())
      driverArgs.insert(driverArgs.end(), {"--gl-provider", options->glProvider});
    std::vector<OutputPath> files;
    if (!options->json.empty()) files.push_back({"--json", options->json});
    checkOutputs(files, {{"--out", options->out}});
    if (!options->json.empty()) refuseJsonOnOwnFiles(options->json, options->out);
    sweep::SweepOptions sweepOptions;
    sweepOptions.executable = executable;
    sweepOptions.backends = splitBackendList(options->backend);
    sweepOptions.outDir = options->out;
    sweepOptions.quick = options->quick;
    sweepOptions.timeoutSeconds = options->timeout;
    sweepOptions.driverArgs = driverArgs;
    sweepOptions.builtins = !options->noBuiltins;
    sweepOptions.listings = options->listings;
    sweepOptions.shadersDir = options->shaders;
    // Ctrl-C stops the drivers' children and the sweep at its next step
    // (sweep_run.cpp), removing what it had written; a signal that comes
    // once the results are being written lets them finish.
    const InterruptFlag interrupt;
    // A driver that does not come up here stops the sweep before it starts.
    const std::vector<BackendProbe> probes =
        probeBackends(executable, sweepOptions.backends, driverArgs);
    for (const BackendProbe& probe : probes) {
      if (!probe.up)
        throw SetupError(fmt::format(
            "backend {} does not come up here: {}{}", probe.backend, probe.problem,
            probe.problem.find("snell devices") == std::string::npos ? " (`snell devices`)" : ""));
      sweepOptions.rules.push_back(precisionRulesForApi(probe.driver.api));
    }
    const fs::path made = firstMissingFolder(options->out);
    sweep::SweepResult result = [&] {
      try {
        return sweep::runSweep(sweepOptions);
      } catch (const Interrupted&) {
        std::error_code ignored;
        if (!made.empty()) fs::remove_all(made, ignored);  // the --out folder it made, empty
        throw;
      }
    }();
    for (std::size_t k = 0; k < probes.size(); ++k)
      result.sweeps[k + 1].renderer = probes[k].driver.renderer;
    // Every point of a backend out of time is more likely a limit set too
    // short than a driver that hangs on all of them: said beside the table.
    for (const sweep::BackendSweep& s : result.sweeps)
      if (!s.points.empty() && std::all_of(s.points.begin(), s.points.end(),
                                           [](const sweep::Observation& o) { return o.timedOut; }))
        printMessage(stderr,
                     "snell: note: every point on {} ran out of time: is --timeout {} s too short "
                     "for this machine? (the default is 300)\n",
                     s.backend, options->timeout);
    const fs::path json =
        options->json.empty() ? fs::path(options->out) / "sweep.json" : fs::path(options->json);
    sweep::writeSweepJson(result, json);
    sweep::printSweepTable(result, stdout);
    // With --json elsewhere, an earlier sweep's charts still go with the
    // sweep.json in --out.
    if (options->noCharts && isAtOrWithin(json, fs::path(options->out) / "sweep.json"))
      sweep::removeEarlierSweepCharts(options->out);
    else if (!options->noCharts)
      for (const fs::path& chart : sweep::writeSweepCharts(result, options->out))
        fmt::print("chart: {}\n", chart.string());
    fmt::print("{} points on {} backend(s) and the oracle, {} Fresnel method samples; JSON: {}\n",
               result.points.size(), sweepOptions.backends.size(), result.methodSamples.size(),
               json.string());
    fmt::print("wall time: {:.1f} s (sweep and classification {:.1f} s)\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
               result.wallSeconds);
    if (const int signal = interrupt.signal())
      throw Interrupted(signal, fmt::format("{} came as the sweep's results were being written; "
                                            "they were written whole",
                                            signalName(signal)));
    bool implementation = false;
    for (const sweep::Break& b : result.breaks)
      implementation = implementation || b.cls == sweep::BreakClass::Implementation;
    for (const sweep::ListingBreak& b : result.listings.breaks)
      implementation = implementation || b.cls == sweep::BreakClass::Implementation;
    if (implementation) return 1;
    return 0;
  };
}

}  // namespace snell::cli
