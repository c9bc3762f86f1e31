#pragma once
// The options that choose backends and drivers, shared by run, bless,
// worker, eval and devices; names come from the backend registry.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace snell::cli {

// "gl,vk" -> {"gl", "vk"}.
std::vector<std::string> splitBackendList(const std::string& list);

// Why `name` is not a registered backend (the registry's message), or ""
// when it is: the check of every --backend option.
std::string unknownBackendReason(const std::string& name);

// --backend (registered names, comma-separated, or all), --device, --gl-provider.
void addBackendOptions(CLI::App& sub, std::string& backend, std::string& device,
                       std::string& glProvider);

// Every registered name, one per line with its description, for --help.
std::string describeBackends();

}  // namespace snell::cli
