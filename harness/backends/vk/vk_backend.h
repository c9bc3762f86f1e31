#pragma once
#include <memory>

#include "backends/backend.h"

namespace snell {
// Vulkan on any ICD; lavapipe unless VK_DRIVER_FILES says otherwise.
std::unique_ptr<Backend> makeVkBackend(const BackendOptions& options);
}  // namespace snell
