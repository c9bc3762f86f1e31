#pragma once
// The options that choose backends and drivers, shared by run, bless,
// worker, eval, serve, sweep and devices; names come from the backend registry.
#include <CLI/CLI.hpp>
#include <string>
#include <vector>

namespace snell::cli {

// "gl,vk" -> {"gl", "vk"}.
std::vector<std::string> splitBackendList(const std::string& list);

// Why `name` is not a registered backend (the registry's message), or ""
// when it is: the check of every --backend option.
std::string unknownBackendReason(const std::string& name);

// Why a comma-joined list of backends is not one (an empty list, an
// unknown name), or ""; `all` passes where `allowAll`.
std::string backendListReason(const std::string& list, bool allowAll);

// Throws UsageError where a given --device or --gl-provider would be
// passed over without a word, every backend in `names` ignoring it (the
// oracle reads neither). "all" may run a backend that reads either, and
// passes.
void requireDriverOptionsRead(const std::vector<std::string>& names, const std::string& device,
                              const std::string& glProvider);

// --device and --gl-provider: which device, and which OpenGL context
// provider, a backend's driver is brought up on.
void addDriverOptions(CLI::App& sub, std::string& device, std::string& glProvider);

// --backend (registered names, comma-separated, or all), --device, --gl-provider.
void addBackendOptions(CLI::App& sub, std::string& backend, std::string& device,
                       std::string& glProvider);

// Every registered name, one per line with its description, for --help.
std::string describeBackends();

}  // namespace snell::cli
