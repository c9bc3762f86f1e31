#include "backends/gl/gl_named_driver.h"

#include <fmt/format.h>

namespace snell {

std::string whyNotTheNamedDriver(const std::string& backend, const std::string& rendererPrefix,
                                 const DriverInfo& got, const std::string& gallium) {
  if (got.renderer.rfind(rendererPrefix, 0) == 0) return "";
  const std::string came = fmt::format("{} is {}, but its context came up on {} (OpenGL {})",
                                       backend, rendererPrefix, got.renderer, got.apiVersion);
  if (got.apiVersion.find("Mesa") == std::string::npos)
    return came +
           ": that driver is not Mesa's, so the variables that choose among Mesa's drivers do "
           "nothing; run a GPU's own driver as gl:gpu";
  if (!gallium.empty())
    return came + fmt::format(
                      ": GALLIUM_DRIVER={} chose it; unset it, or run the backend named for that "
                      "driver (`snell devices`)",
                      gallium);
  return came + ": run the backend named for that driver (`snell devices`)";
}

}  // namespace snell
