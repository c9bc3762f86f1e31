// `snell devices`: what each API sees on this machine, and which backends
// come up on it (each asked in a worker process of its own, with the
// environment its driver needs). `snell --version --drivers` prints the
// second half.
#include <fmt/format.h>

#include <filesystem>

#include "backends/backend_registry.h"
#include "cli/backend_options.h"
#include "cli/commands.h"
#include "runner/backend_probe.h"

namespace snell::cli {

namespace {
std::vector<std::string> probeArgs(const std::string& device, const std::string& glProvider) {
  std::vector<std::string> args;
  if (!device.empty()) args.insert(args.end(), {"--device", device});
  if (!glProvider.empty()) args.insert(args.end(), {"--gl-provider", glProvider});
  return args;
}
}  // namespace

int printBackendDrivers(const std::vector<std::string>& workerArgs) {
  const std::vector<std::string> names = backendRegistry().names();
  const std::vector<BackendProbe> probes =
      probeBackends(std::filesystem::read_symlink("/proc/self/exe").string(), names, workerArgs);
  for (const BackendProbe& p : probes) {
    if (p.up)
      fmt::print("  {:<16} {} | {} {} | {} | golden key {}\n", p.backend, p.driver.renderer,
                 p.driver.api, p.driver.apiVersion, p.driver.driverVersion,
                 backendRegistry().find(p.backend).goldenKey);
    else
      fmt::print("  {:<16} not available: {}\n", p.backend, p.problem);
  }
  return 0;
}

Command addDevicesCommand(CLI::App& app) {
  CLI::App* sub = app.add_subcommand(
      "devices", "List the devices each API sees and the backends that come up on them");
  struct Options {
    std::string backend, device, glProvider;
  };
  auto options = std::make_shared<Options>();
  sub->add_option("--device", options->device, "As `run --device`, for the backends part");
  sub->add_option("--gl-provider", options->glProvider, "As `run --gl-provider`")
      ->check(CLI::IsMember({"osmesa", "egl"}));
  return [options] {
    fmt::print(
        "Vulkan physical devices (every installed ICD; --device takes the index, the "
        "vendor:device id or a name):\n");
    for (const DeviceListing& d : vkDeviceListing())
      fmt::print("  {:>2}  {}  ({})\n", d.index, d.name, d.detail);
    fmt::print("EGL devices (EGL_EXT_device_enumeration; --device takes the index for gl:gpu):\n");
    for (const DeviceListing& d : glDeviceListing())
      fmt::print("  {:>2}  {}  ({})\n", d.index, d.name, d.detail);
    fmt::print("Backends (`run --backend NAME`; `all` runs every one available):\n");
    return printBackendDrivers(probeArgs(options->device, options->glProvider));
  };
}

}  // namespace snell::cli
