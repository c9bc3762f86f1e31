#pragma once
// Whether each backend's driver comes up on this machine, asked of a
// `snell worker --describe` process per backend (all at once), so the
// asking process loads no driver and a driver that crashes costs nothing.
#include <string>
#include <vector>

#include "backends/backend.h"

namespace snell {

struct BackendProbe {
  std::string backend;
  bool up = false;
  DriverInfo driver;    // when up
  std::string problem;  // when not: the worker's message, or how it died
};

// `workerArgs`: extra worker options (--device, --gl-provider).
std::vector<BackendProbe> probeBackends(const std::string& executable,
                                        const std::vector<std::string>& backends,
                                        const std::vector<std::string>& workerArgs,
                                        double timeoutSeconds = 60);

}  // namespace snell
