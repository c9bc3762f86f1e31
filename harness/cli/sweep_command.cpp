#include <fmt/format.h>

#include <chrono>
#include <filesystem>

#include "backends/backend_registry.h"
#include "cli/backend_options.h"
#include "cli/commands.h"
#include "core/errors.h"
#include "runner/backend_probe.h"
#include "sweep/sweep_charts.h"
#include "sweep/sweep_report.h"
#include "sweep/sweep_run.h"

namespace snell::cli {

Command addSweepCommand(CLI::App& app) {
  CLI::App* sweep = app.add_subcommand(
      "sweep",
      "Sweep refract() and reflect() over incidence angle, eta and bad inputs on the oracle and "
      "each driver, and the Fresnel methods against exact Fresnel; classify every break");
  struct Options {
    std::string backend = "gl,vk";
    std::string out = "snell-out/sweep";
    std::string json;
    bool quick = false;
    bool noCharts = false;
    double timeout = 300;
  };
  auto options = std::make_shared<Options>();
  sweep
      ->add_option("--backend", options->backend,
                   "Drivers to sweep, joined by commas (`snell devices`); the oracle is always "
                   "swept")
      ->check([](const std::string& value) -> std::string {
        if (splitBackendList(value).empty()) return "name at least one backend";
        for (const std::string& name : splitBackendList(value)) {
          try {
            backendRegistry().find(name);
          } catch (const UsageError& error) {
            return error.what();
          }
        }
        return "";
      });
  sweep->add_option("--out", options->out, "Folder for the charts, their data and the input");
  sweep->add_option("--json", options->json, "Breaks as JSON (default OUT/sweep.json)");
  sweep->add_flag("--quick", options->quick, "A few etas and angles (for tests)");
  sweep->add_flag("--no-charts", options->noCharts, "Skip the gnuplot charts");
  sweep->add_option("--timeout", options->timeout, "Seconds each driver may take")
      ->check(CLI::PositiveNumber);
  sweep->footer(
      "Each break is implementation (a backend left its spec interval, or crashed), undefined\n"
      "(the spec allows anything there) or method (a Fresnel method past its error bound\n"
      "against exact Fresnel, or outside its physical range). Exit 1 when an implementation\n"
      "break was found.");
  return [options] {
    namespace fs = std::filesystem;
    const auto start = std::chrono::steady_clock::now();
    const std::string executable = fs::read_symlink("/proc/self/exe").string();
    sweep::SweepOptions sweepOptions;
    sweepOptions.executable = executable;
    sweepOptions.backends = splitBackendList(options->backend);
    sweepOptions.outDir = options->out;
    sweepOptions.quick = options->quick;
    sweepOptions.timeoutSeconds = options->timeout;
    // A driver that does not come up here stops the sweep before it starts.
    const std::vector<BackendProbe> probes = probeBackends(executable, sweepOptions.backends, {});
    for (const BackendProbe& probe : probes)
      if (!probe.up)
        throw SetupError(fmt::format("backend {} does not come up here: {} (`snell devices`)",
                                     probe.backend, probe.problem));
    sweep::SweepResult result = sweep::runSweep(sweepOptions);
    for (std::size_t k = 0; k < probes.size(); ++k)
      result.sweeps[k + 1].renderer = probes[k].driver.renderer;
    const fs::path json =
        options->json.empty() ? fs::path(options->out) / "sweep.json" : fs::path(options->json);
    sweep::writeSweepJson(result, json);
    sweep::printSweepTable(result, stdout);
    if (!options->noCharts)
      for (const fs::path& chart : sweep::writeSweepCharts(result, options->out))
        fmt::print("chart: {}\n", chart.string());
    fmt::print("{} points on {} backend(s) and the oracle, {} Fresnel method samples; JSON: {}\n",
               result.points.size(), sweepOptions.backends.size(), result.methodSamples.size(),
               json.string());
    fmt::print("wall time: {:.1f} s (sweep and classification {:.1f} s)\n",
               std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
               result.wallSeconds);
    bool implementation = false;
    for (const sweep::Break& b : result.breaks)
      implementation = implementation || b.cls == sweep::BreakClass::Implementation;
    return implementation ? 1 : 0;
  };
}

}  // namespace snell::cli
