#include "backends/backend.h"

#include "backends/gl/gl_backend.h"
#include "backends/vk/vk_backend.h"
#include "core/errors.h"

namespace snell {

std::unique_ptr<Backend> makeBackend(const std::string& name, const BackendOptions& options) {
  if (name == "gl") return makeGlBackend(options);
  if (name == "vk") return makeVkBackend(options);
  throw UsageError("unknown backend '" + name + "': use gl or vk");
}

}  // namespace snell
