#include "backends/gl/gl_named_driver.h"

#include <fmt/format.h>

namespace snell {

std::string whyNotTheNamedDriver(const std::string& backend, const std::string& rendererPrefix,
                                 const DriverInfo& got, const UserDriverVariables& user) {
  if (got.renderer.rfind(rendererPrefix, 0) == 0) {
    // llvmpipe at another width is another driver (gl:llvmpipe-128).
    if (user.vectorWidth.empty() || got.renderer.find("llvmpipe") == std::string::npos) return "";
    return fmt::format(
        "{} is llvmpipe at its native vector width, and LP_NATIVE_VECTOR_WIDTH={} is set in the "
        "environment ({}): unset it, or run the backend named for that width (gl:llvmpipe-128)",
        backend, user.vectorWidth, got.renderer);
  }
  const std::string came = fmt::format("{} is {}, but its context came up on {} (OpenGL {})",
                                       backend, rendererPrefix, got.renderer, got.apiVersion);
  if (got.apiVersion.find("Mesa") == std::string::npos)
    return came +
           ": that driver is not Mesa's, so the variables that choose among Mesa's drivers do "
           "nothing; run a GPU's own driver as gl:gpu";
  if (!user.galliumDriver.empty())
    return came + fmt::format(
                      ": GALLIUM_DRIVER={} chose it; unset it, or run the backend named for that "
                      "driver (`snell devices`)",
                      user.galliumDriver);
  return came + ": run the backend named for that driver (`snell devices`)";
}

}  // namespace snell
