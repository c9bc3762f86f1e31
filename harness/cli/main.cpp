// snell: a conformance suite and CI gate for reflection and refraction shaders.
#include <fmt/format.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>
#include <iostream>
#include <map>
#include <string>

#include "cli/commands.h"
#include "core/errors.h"
#include "core/heap_reuse.h"
#include "core/message.h"

namespace {

// What a command wrote to standard output reached it: a full disk or a
// failed pipe is exit 2 with a message, never a silent success (`compare
// --json > /dev/full` exited 0).
int withOutputWritten(int code) {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !std::ferror(stdout) && std::cout.good()) return code;
  snell::printMessage(stderr,
                      "snell: cannot write to standard output{}; what it holds is cut short\n",
                      error != 0 ? fmt::format(" ({})", std::strerror(error)) : "");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  snell::keepFreedMemoryForReuse();
  CLI::App app{
      "snell: runs published reflection/refraction GLSL listings on OpenGL and Vulkan "
      "and holds the results against a spec-derived CPU oracle"};
  bool version = false, drivers = false;
  app.add_flag("--version", version, "Print snell's version and exit");
  app.add_flag("--drivers", drivers, "With --version: each backend's renderer and versions");
  app.require_subcommand(0, 1);
  std::map<const CLI::App*, snell::cli::Command> commands;
  for (auto add :
       {snell::cli::addRunCommand, snell::cli::addListCommand, snell::cli::addEvalCommand,
        snell::cli::addServeCommand, snell::cli::addBlessCommand, snell::cli::addMergeCommand,
        snell::cli::addCompareCommand, snell::cli::addReportCommand, snell::cli::addWorkerCommand,
        snell::cli::addDevicesCommand, snell::cli::addSweepCommand, snell::cli::addBenchCommand,
        snell::cli::addAdviseCommand, snell::cli::addInitCommand}) {
    const std::size_t before = app.get_subcommands({}).size();
    snell::cli::Command run = add(app);
    commands[app.get_subcommands({}).at(before)] = std::move(run);
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& help) {
    return app.exit(help);
  } catch (const CLI::CallForAllHelp& help) {
    return app.exit(help);
  } catch (const CLI::ParseError& error) {
    // A first word that is no command: say which are, not "not expected".
    if (dynamic_cast<const CLI::ExtrasError*>(&error) && app.get_subcommands().empty() &&
        !app.remaining().empty()) {
      std::string names;
      for (const CLI::App* sub : app.get_subcommands({}))
        if (!sub->get_group().empty()) names += (names.empty() ? "" : ", ") + sub->get_name();
      snell::printMessage(stderr,
                          "snell: unknown command '{}'; the commands are {} (snell --help)\n",
                          app.remaining().front(), names);
      return 2;
    }
    app.exit(error);
    return 2;
  }
  try {
    if (drivers && !version) {
      snell::printMessage(stderr,
                          "snell: --drivers goes with --version: snell --version --drivers\n");
      return 2;
    }
    if (version) {
      fmt::print("snell {}\n", SNELL_VERSION);
      return withOutputWritten(drivers ? snell::cli::printBackendDrivers({}) : 0);
    }
    if (app.get_subcommands().empty()) {
      snell::printMessage(stderr, "snell: name a command (snell --help lists them)\n");
      return 2;
    }
    for (const auto& [sub, run] : commands)
      if (sub->parsed()) return withOutputWritten(run());
  } catch (const snell::Interrupted& stopped) {
    snell::printMessage(stderr, "snell: {}\n", stopped.what());
    return 128 + stopped.signal;
  } catch (const snell::UsageError& error) {
    snell::printMessage(stderr, "snell: {}\n", error.what());
    return 2;
  } catch (const snell::SetupError& error) {
    snell::printMessage(stderr, "snell: set-up error: {}\n", error.what());
    return 2;
  } catch (const std::exception& error) {
    // fmt::print throws when standard output takes no more.
    if (std::ferror(stdout)) return withOutputWritten(2);
    snell::printMessage(stderr, "snell: internal error: {}\n", error.what());
    return 2;
  }
  return 2;
}
