#pragma once
// Every backend snell can run, by name. An entry says how to make the
// backend, the environment its worker needs before any driver loads, what
// it can run and the key its goldens are kept under. A new backend is a
// folder of its own and one registration call in backend_registry.cpp.
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "backends/backend.h"
#include "backends/backend_capabilities.h"

namespace snell {

struct BackendEntry {
  std::string name;         // "gl", "gl:softpipe", "vk"
  std::string description;  // one line for `snell devices` and --help
  std::string family;  // "gl" or "vk": the API key manifests use (not_supported, compile_error)
  std::vector<std::pair<std::string, std::string>> environment;  // set before the driver loads
  BackendCapabilities capabilities;
  std::string goldenKey;  // golden/<case>/<goldenKey>.exr; backends on the same driver share it
  // Whether `--backend all` includes it when it comes up (a GPU-only backend
  // on a machine without one simply does not come up).
  bool inAll = true;
  // Which driver options its `make` reads: `--device` (a device to pick)
  // and `--gl-provider` (a context provider in place of its own). A command
  // refuses either when no backend it runs reads it.
  bool takesDevice = false;
  bool takesGlProvider = false;
  std::function<std::unique_ptr<Backend>(const BackendEntry&, const BackendOptions&)> make;
};

// Each API's registrations, one function per backend folder.
std::vector<BackendEntry> glBackendEntries();
std::vector<BackendEntry> vkBackendEntries();

// A device an API can see, for `snell devices`.
struct DeviceListing {
  std::string api;     // "Vulkan", "EGL"
  int index = 0;       // what --device takes
  std::string name;    // "llvmpipe (LLVM 15.0.6, 256 bits)", "/dev/dri/renderD128", "software"
  std::string detail;  // driver, versions, vendor:device id
};

// What each API sees here, loading its library in this process; an API
// that cannot be brought up gives one entry whose detail says why.
std::vector<DeviceListing> glDeviceListing();
std::vector<DeviceListing> vkDeviceListing();

class BackendRegistry {
 public:
  void add(BackendEntry entry);  // a name may be registered once
  const std::vector<BackendEntry>& entries() const { return entries_; }
  // Throws UsageError listing the registered names.
  const BackendEntry& find(const std::string& name) const;
  std::vector<std::string> names() const;

 private:
  std::vector<BackendEntry> entries_;
};

// Every backend of this build, registered once on first use.
const BackendRegistry& backendRegistry();

// Sets the entry's environment in this process (overwriting), so that a
// worker's driver sees it when it loads.
void applyBackendEnvironment(const BackendEntry& entry);

}  // namespace snell
