#pragma once
// Each subcommand registers its options on the app and returns the function
// that runs it. The functions return the process exit code: 0 nothing
// failed, 1 something failed, 2 usage or set-up error.
#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace snell::cli {

using Command = std::function<int()>;

Command addRunCommand(CLI::App& app);
Command addListCommand(CLI::App& app);
Command addEvalCommand(CLI::App& app);
Command addServeCommand(CLI::App& app);
Command addWorkerCommand(CLI::App& app);
Command addBlessCommand(CLI::App& app);
Command addMergeCommand(CLI::App& app);
Command addCompareCommand(CLI::App& app);
Command addReportCommand(CLI::App& app);
Command addDevicesCommand(CLI::App& app);
Command addSweepCommand(CLI::App& app);
Command addBenchCommand(CLI::App& app);
Command addAdviseCommand(CLI::App& app);
Command addInitCommand(CLI::App& app);

// Each registered backend: its renderer and versions, or why it does not
// come up here (asked of worker processes). Returns 0.
int printBackendDrivers(const std::vector<std::string>& workerArgs);

// The repository's own listings and goldens, where the binary was built from.
std::string defaultShadersDir();
std::string defaultGoldenDir();
// The method ladders (one folder each), and where `snell bench` writes
// (and `snell advise` reads, one folder per ladder) by default.
std::string defaultMethodsDir();
std::string defaultBenchDir();

}  // namespace snell::cli
