#pragma once
#include <memory>
#include <string>

#include "backends/backend.h"

namespace snell {
// Vulkan on any ICD. `lavapipeByDefault`: lavapipe unless VK_DRIVER_FILES
// says otherwise; `device` as VulkanDevice takes it.
std::unique_ptr<Backend> makeVkBackend(const std::string& name, bool lavapipeByDefault,
                                       const std::string& device, const BackendOptions& options);
// The registered `vk` backend: lavapipe by default.
std::unique_ptr<Backend> makeVkBackend(const BackendOptions& options);
}  // namespace snell
