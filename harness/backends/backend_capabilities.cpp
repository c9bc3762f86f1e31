#include "backends/backend_capabilities.h"

#include <fmt/format.h>

#include <algorithm>
#include <cstdio>

namespace snell {

int glslVersionOf(const std::string& shaderText) {
  std::size_t at = 0;
  while (at < shaderText.size()) {
    const std::size_t end = std::min(shaderText.find('\n', at), shaderText.size());
    const std::size_t first = shaderText.find_first_not_of(" \t", at);
    if (first < end && shaderText.compare(first, 8, "#version") == 0) {
      int version = 0;
      if (std::sscanf(shaderText.c_str() + first + 8, "%d", &version) == 1) return version;
    }
    at = end + 1;
  }
  return 110;
}

std::string whyBackendCannotRun(const BackendCapabilities& can, int programGlslVersion,
                                bool compatibilityProfile) {
  if (compatibilityProfile && !can.compatibilityProfile)
    return fmt::format(
        "needs an OpenGL compatibility profile, which this {} backend does not offer", can.api);
  if (can.glslVersion > 0 && programGlslVersion > can.glslVersion)
    return fmt::format("needs GLSL {}; this driver compiles up to {} ({} {}.{} core)",
                       programGlslVersion, can.glslVersion, can.api, can.coreVersion / 10,
                       can.coreVersion % 10);
  return "";
}

}  // namespace snell
