#pragma once
// A GL backend's name says which driver it runs, and its goldens and
// expectations are kept under that name: a context that came up on another
// driver (GALLIUM_DRIVER=softpipe left in the environment, or a machine
// whose libEGL loads only a GPU vendor's driver) is refused, not run under
// the name.
#include <string>

#include "backends/backend.h"

namespace snell {

// Empty when `got`'s renderer starts with `rendererPrefix` (an empty
// prefix takes any driver); else why the backend cannot run, and what to do.
// `gallium` is a GALLIUM_DRIVER the user set ("" when unset, or when the
// backend's own environment sets it).
std::string whyNotTheNamedDriver(const std::string& backend, const std::string& rendererPrefix,
                                 const DriverInfo& got, const std::string& gallium);

}  // namespace snell
