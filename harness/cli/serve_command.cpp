#include <fmt/format.h>
#include <unistd.h>

#include "backends/backend.h"
#include "cli/backend_options.h"
#include "cli/commands.h"
#include "cli/eval_setup.h"
#include "cli/option_checks.h"
#include "core/errors.h"
#include "core/message.h"
#include "runner/eval_server.h"
#include "runner/eval_server_protocol.h"
#include "runner/interrupt_flag.h"

namespace snell::cli {

Command addServeCommand(CLI::App& app) {
  CLI::App* serve = app.add_subcommand(
      "serve",
      "Keep one backend's driver up and answer `snell eval --server` on it: a small eval then "
      "costs no driver start");
  struct Options {
    std::string backend;
    std::string device;
    std::string glProvider;
    std::string socket;
    std::vector<std::string> watch;
    unsigned idleExit = 1800;
  };
  auto options = std::make_shared<Options>();
  serve->add_option("--backend", options->backend, "The backend to serve (`snell devices`)")
      ->required()
      ->check(unknownBackendReason);
  addDriverOptions(*serve, options->device, options->glProvider);
  serve
      ->add_option("--socket", options->socket,
                   "Unix socket to listen at (default $XDG_RUNTIME_DIR/snell-serve-BACKEND.sock, "
                   "else /tmp/snell-serve-UID-BACKEND.sock)")
      ->check(nonEmptyPath());
  serve->add_option("--watch", options->watch,
                    "Also stop when this file changes (repeatable): the loaded driver libraries "
                    "and snell itself are always watched");
  serve
      ->add_option("--idle-exit", options->idleExit,
                   "Stop after this many seconds without a request (0: never)")
      ->check(wholeNumber())
      ->check(CLI::Range(0, 604800))  // a week; past the type, CLI11 says only "Could not convert"
      ->capture_default_str();
  serve->footer(
      R"(Runs in the foreground until SIGINT or SIGTERM, --idle-exit, or a changed file: before
each request it checks every file of code it has loaded (its driver libraries, snell itself)
and any --watch file; when one has changed it refuses the request with the file's name and
stops, so a rebuilt driver is never judged by the old one. Requests are answered one at a
time, each exactly as `snell eval --backend BACKEND` would answer it, and logged on stderr.
Only its own user's `snell eval --server` of the same build is answered.)");
  return [options] {
    // First: a signal from here on stops the server cleanly (no socket
    // file left behind), whatever it is doing.
    const InterruptFlag interrupt;
    requireDriverOptionsRead({options->backend}, options->device, options->glProvider);
    std::unique_ptr<Backend> backend =
        makeEvalBackend(options->backend, options->device, options->glProvider);
    ServeOptions serveOptions;
    serveOptions.socketPath =
        options->socket.empty() ? defaultServeSocket(options->backend) : options->socket;
    serveOptions.watch = options->watch;
    serveOptions.idleExit = std::chrono::seconds(options->idleExit);
    serveOptions.eval = evalOptionsFromEnvironment();
    EvalServer server(*backend, options->backend, serveOptions, interrupt);
    if (interrupt.signal()) {
      printMessage(stderr, "snell serve: stopped by signal {} while starting\n",
                   interrupt.signal());
      return 0;
    }
    const DriverInfo& driver = backend->driverInfo();
    printMessage(stderr, "snell serve: {} ({}) on {}, watching {} files; pid {}\n",
                 options->backend, driver.renderer, serveOptions.socketPath, server.watchedFiles(),
                 getpid());
    std::fflush(stderr);
    const std::string why = server.run(stderr);
    printMessage(stderr, "snell serve: stopped: {}\n", why);
    return 0;
  };
}

}  // namespace snell::cli
