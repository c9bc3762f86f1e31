#pragma once
#include <memory>

#include "backends/backend.h"

namespace snell {
// OpenGL through OSMesa (llvmpipe, or softpipe with GALLIUM_DRIVER=softpipe).
std::unique_ptr<Backend> makeGlBackend(const BackendOptions& options);
}  // namespace snell
