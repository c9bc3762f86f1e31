#pragma once
// A VkShaderModule that destroys itself.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "backends/vk/vk_device.h"

namespace snell::vk {

class ShaderModule {
 public:
  ShaderModule(const VulkanDevice& device, std::span<const std::uint32_t> spirv);
  ~ShaderModule();
  ShaderModule(const ShaderModule&) = delete;
  ShaderModule& operator=(const ShaderModule&) = delete;

  VkShaderModule handle() const { return module_; }

 private:
  const VulkanDevice& device_;
  VkShaderModule module_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
