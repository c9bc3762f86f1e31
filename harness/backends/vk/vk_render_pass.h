#pragma once
// The render pass every render pipeline and target is built for: one
// RGBA32F colour attachment (cleared, then left ready to be copied out) and
// one D32 depth attachment (cleared to 1, then discarded).
#include <vulkan/vulkan.h>

#include "backends/vk/vk_device.h"

namespace snell::vk {

inline constexpr VkFormat kColourFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

class RenderPass {
 public:
  explicit RenderPass(const VulkanDevice& device);
  ~RenderPass();
  RenderPass(const RenderPass&) = delete;
  RenderPass& operator=(const RenderPass&) = delete;

  VkRenderPass handle() const { return pass_; }

 private:
  const VulkanDevice& device_;
  VkRenderPass pass_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
