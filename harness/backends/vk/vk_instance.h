#pragma once
// The VkInstance, with the Khronos validation layer and a debug messenger
// feeding a ValidationLog when validation is asked for.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "backends/vk/vk_validation_log.h"

namespace snell::vk {

class VulkanInstance {
 public:
  // Throws SetupError saying what to install or set when Vulkan cannot start.
  // `lavapipeByDefault`: point the loader at lavapipe unless the user named
  // a driver (vk_driver_selection.h); off, the loader sees every ICD.
  explicit VulkanInstance(bool validation, bool lavapipeByDefault = true);
  ~VulkanInstance();
  VulkanInstance(const VulkanInstance&) = delete;
  VulkanInstance& operator=(const VulkanInstance&) = delete;

  VkInstance handle() const { return instance_; }
  std::uint32_t apiVersion() const { return apiVersion_; }
  ValidationLog& validationLog() { return log_; }

 private:
  ValidationLog log_;  // first member: the messenger points at it until the end
  VkInstance instance_ = VK_NULL_HANDLE;
  VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
  std::uint32_t apiVersion_ = VK_API_VERSION_1_1;
};

}  // namespace snell::vk
