#include "cli/backend_options.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cstddef>
#include <sstream>

#include "backends/backend_registry.h"
#include "cli/option_checks.h"
#include "core/errors.h"

namespace snell::cli {

std::vector<std::string> splitBackendList(const std::string& list) {
  std::vector<std::string> names;
  std::stringstream in(list);
  for (std::string name; std::getline(in, name, ',');)
    if (!name.empty()) names.push_back(name);
  return names;
}

std::string unknownBackendReason(const std::string& name) {
  try {
    backendRegistry().find(name);
  } catch (const UsageError& error) {
    return error.what();
  }
  return "";
}

std::string describeBackends() {
  std::string text;
  for (const BackendEntry& e : backendRegistry().entries())
    text += fmt::format("  {:<16} {}\n", e.name, e.description);
  return text;
}

std::string backendListReason(const std::string& list, bool allowAll) {
  if (allowAll && list == "all") return "";
  const std::vector<std::string> names = splitBackendList(list);
  if (names.empty())
    return allowAll ? "name at least one backend, or all" : "name at least one backend";
  // "gl," or "gl,,vk" (an unset variable in a CI script) ran what was left.
  if (list.front() == ',' || list.back() == ',' || list.find(",,") != std::string::npos)
    return fmt::format("'{}' has an empty name between its commas; name each backend", list);
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (std::string reason = unknownBackendReason(names[k]); !reason.empty()) return reason;
    // Twice in one run, a backend's every case would run twice and write
    // two records under one key, which merge and compare refuse.
    if (std::find(names.begin(), names.begin() + static_cast<std::ptrdiff_t>(k), names[k]) !=
        names.begin() + static_cast<std::ptrdiff_t>(k))
      return fmt::format("`{}` is named twice; name each backend once", names[k]);
  }
  return "";
}

namespace {

// "a", "a and b", "a, b and c".
std::string spokenList(const std::vector<std::string>& items) {
  if (items.size() < 2) return fmt::format("{}", fmt::join(items, ""));
  return fmt::format("{} and {}", fmt::join(items.begin(), items.end() - 1, ", "), items.back());
}

std::string unreadReason(const std::vector<std::string>& names, const std::string& option,
                         const std::string& value, const char* what, bool BackendEntry::*reads) {
  std::vector<std::string> readers;
  for (const BackendEntry& e : backendRegistry().entries())
    if (e.*reads) readers.push_back(e.name);
  for (const std::string& name : names)
    if (name != "oracle" && backendRegistry().find(name).*reads) return "";
  return fmt::format(
      "{} {}: {} {} {} (only {} {}); drop {}, or run one of those", option, value,
      names.size() == 1 ? names.front() : fmt::format("none of {}", fmt::join(names, ", ")),
      names.size() == 1 ? "does not take" : "takes", what, spokenList(readers),
      readers.size() == 1 ? "does" : "do", option);
}

}  // namespace

void requireDriverOptionsRead(const std::vector<std::string>& names, const std::string& device,
                              const std::string& glProvider) {
  if (names.empty() || (names.size() == 1 && names.front() == "all")) return;
  std::string reason;
  if (!device.empty())
    reason = unreadReason(names, "--device", device, "a device", &BackendEntry::takesDevice);
  if (reason.empty() && !glProvider.empty())
    reason = unreadReason(names, "--gl-provider", glProvider, "an OpenGL context provider",
                          &BackendEntry::takesGlProvider);
  if (!reason.empty()) throw UsageError(reason);
}

void addDriverOptions(CLI::App& sub, std::string& device, std::string& glProvider) {
  sub.add_option("--device", device,
                 "Vulkan: a physical device by index, vendor:device id (hex) or name; EGL "
                 "device backends (gl:gpu): a device index")
      ->check(nonEmpty("device", "name one (`snell devices` lists them)"));
  sub.add_option("--gl-provider", glProvider,
                 "OpenGL context provider in place of the backend's own: osmesa or egl")
      ->check(CLI::IsMember({"osmesa", "egl"}));
}

void addBackendOptions(CLI::App& sub, std::string& backend, std::string& device,
                       std::string& glProvider) {
  sub.add_option("--backend", backend,
                 "Backends to run: names joined by commas, or all (every one that comes up "
                 "here; `snell devices`)")
      ->check([](const std::string& value) { return backendListReason(value, true); })
      ->capture_default_str();
  addDriverOptions(sub, device, glProvider);
}

}  // namespace snell::cli
