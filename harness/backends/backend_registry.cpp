#include "backends/backend_registry.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cstdlib>

#include "backends/driver_variables.h"
#include "core/errors.h"

namespace snell {

void BackendRegistry::add(BackendEntry entry) {
  for (const BackendEntry& e : entries_)
    if (e.name == entry.name) throw std::logic_error("backend registered twice: " + entry.name);
  entries_.push_back(std::move(entry));
}

const BackendEntry& BackendRegistry::find(const std::string& name) const {
  for (const BackendEntry& e : entries_)
    if (e.name == name) return e;
  throw UsageError(fmt::format("unknown backend '{}': use one of {} (`snell devices` lists them)",
                               name, fmt::join(names(), ", ")));
}

std::vector<std::string> BackendRegistry::names() const {
  std::vector<std::string> out;
  for (const BackendEntry& e : entries_) out.push_back(e.name);
  return out;
}

const BackendRegistry& backendRegistry() {
  static const BackendRegistry registry = [] {
    BackendRegistry r;
    for (BackendEntry& e : glBackendEntries()) r.add(std::move(e));
    for (BackendEntry& e : vkBackendEntries()) r.add(std::move(e));
    return r;
  }();
  return registry;
}

void applyBackendEnvironment(const BackendEntry& entry) {
  for (const auto& [name, value] : entry.environment) setDriverVariable(entry.name, name, value);
}

std::unique_ptr<Backend> makeBackend(const std::string& name, const BackendOptions& options) {
  const BackendEntry& entry = backendRegistry().find(name);
  applyBackendEnvironment(entry);
  return entry.make(entry, options);
}

}  // namespace snell
