#pragma once
// The render pass render pipelines and targets are built for: RGBA32F
// colour attachments (the listing's output, then one per fragment probe;
// cleared, then left ready to be copied out) and one D32 depth attachment
// (cleared to 1, then discarded), which comes last.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "backends/vk/vk_device.h"

namespace snell::vk {

inline constexpr VkFormat kColourFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

class RenderPass {
 public:
  RenderPass(const VulkanDevice& device, std::uint32_t colourTargets);
  ~RenderPass();
  RenderPass(const RenderPass&) = delete;
  RenderPass& operator=(const RenderPass&) = delete;

  VkRenderPass handle() const { return pass_; }
  std::uint32_t colourTargets() const { return colourTargets_; }

 private:
  const VulkanDevice& device_;
  std::uint32_t colourTargets_ = 1;
  VkRenderPass pass_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
