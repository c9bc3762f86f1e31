#include "cli/commands.h"
#include "runner/worker.h"

namespace snell::cli {

Command addWorkerCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "worker", "Internal: run cases named on standard input on one backend (started by `run`)");
  sub->group("");  // not listed in --help: users run `snell run`
  auto options = std::make_shared<WorkerOptions>();
  sub->add_option("--backend", options->backend, "A registered backend")->required();
  sub->add_option("--shaders", options->shaders, "Folder of listings")->required();
  sub->add_flag("--validation", options->validation, "Vulkan validation layer");
  sub->add_option("--device", options->device, "As `run --device`");
  sub->add_option("--gl-provider", options->glProvider, "As `run --gl-provider`");
  sub->add_flag("--describe", options->describe,
                "Bring the backend up, print its driver as JSON and exit");
  sub->add_option("--out", options->outDir, "Folder for images, heat maps and masks")->required();
  sub->add_option("--golden", options->goldenDir, "Folder of goldens; empty for none")->required();
  sub->add_option("--run-id", options->runId,
                  "Share each case's CPU reference image with the run's other workers");
  sub->add_option("--spawned-at", options->spawnedAtNs,
                  "Steady-clock nanoseconds when the supervisor spawned this worker");
  sub->add_option(
      "--oracle-store", options->oracleStore,
      "Folder of oracle results and compiled programs kept across runs (as `run --oracle-cache`)");
  sub->add_option("--bless-flags", options->blessFlags,
                  "The user's --shaders/--golden flags, for the advice to bless a golden");
  return [options] { return runWorker(*options); };
}

}  // namespace snell::cli
