#include "backends/gl/gl_named_driver.h"

#include <fmt/format.h>

#include "backends/driver_variables.h"

namespace snell {

std::string whyNotTheNamedDriver(const std::string& backend, const std::string& rendererPrefix,
                                 const DriverInfo& got, const UserDriverVariables& user) {
  if (got.renderer.rfind(rendererPrefix, 0) == 0) {
    // llvmpipe at another width is another driver (gl:llvmpipe-128); zink
    // runs on lavapipe, which has no backend of its own for another width.
    if (user.vectorWidth.empty() || got.renderer.find("llvmpipe") == std::string::npos) return "";
    const bool zink = got.renderer.rfind("zink", 0) == 0;
    return whyNotAtNativeVectorWidth(backend, zink ? "zink on lavapipe" : "llvmpipe", got.renderer,
                                     user.vectorWidth, user.vectorWidthSetBy,
                                     zink ? "" : "gl:llvmpipe-128");
  }
  const std::string came = fmt::format("{} is {}, but its context came up on {} (OpenGL {})",
                                       backend, rendererPrefix, got.renderer, got.apiVersion);
  if (got.apiVersion.find("Mesa") == std::string::npos)
    return came +
           ": that driver is not Mesa's, so the variables that choose among Mesa's drivers do "
           "nothing; run a GPU's own driver as gl:gpu";
  if (!user.galliumDriver.empty() && !user.galliumDriverSetBy.empty())
    return came + fmt::format(
                      ": GALLIUM_DRIVER={}, which {} set for its own driver earlier in this "
                      "process, chose it; run {} in a command of its own",
                      user.galliumDriver, user.galliumDriverSetBy, backend);
  if (!user.galliumDriver.empty())
    return came + fmt::format(
                      ": GALLIUM_DRIVER={} chose it; unset it, or run the backend named for that "
                      "driver (`snell devices`)",
                      user.galliumDriver);
  return came + ": run the backend named for that driver (`snell devices`)";
}

}  // namespace snell
