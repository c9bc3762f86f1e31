#pragma once
// A GL backend's name says which driver it runs, and its goldens and
// expectations are kept under that name: a context that came up on another
// driver (GALLIUM_DRIVER=softpipe left in the environment, or a machine
// whose libEGL loads only a GPU vendor's driver) is refused, not run under
// the name.
#include <string>

#include "backends/backend.h"

namespace snell {

// The variables left in the environment that choose among Mesa's drivers
// ("" when unset, or when the backend's own environment sets them), and
// the backend that set each in this process ("" for the user's own).
struct UserDriverVariables {
  std::string galliumDriver;  // GALLIUM_DRIVER
  std::string vectorWidth;    // LP_NATIVE_VECTOR_WIDTH
  std::string galliumDriverSetBy;
  std::string vectorWidthSetBy;
};

// Empty when `got`'s renderer starts with `rendererPrefix` (an empty
// prefix takes any driver) and no user variable changed the driver; else
// why the backend cannot run, and what to do.
std::string whyNotTheNamedDriver(const std::string& backend, const std::string& rendererPrefix,
                                 const DriverInfo& got, const UserDriverVariables& user);

}  // namespace snell
