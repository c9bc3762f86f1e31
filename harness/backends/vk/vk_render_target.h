#pragma once
// The colour images (one per colour attachment of the pass) and the depth
// image of one render size, and their framebuffer.
// Made on the first render at that size and kept for the next.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "backends/vk/vk_device.h"
#include "backends/vk/vk_device_image.h"

namespace snell::vk {

class RenderTarget {
 public:
  // Throws SetupError when the device cannot render to the formats in vk_render_pass.h.
  RenderTarget(const VulkanDevice& device, VkRenderPass renderPass, std::uint32_t colourTargets,
               std::uint32_t width, std::uint32_t height);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  VkImage colourImage(std::size_t index) const { return colours_.at(index)->image(); }
  std::size_t colourTargets() const { return colours_.size(); }
  VkFramebuffer framebuffer() const { return framebuffer_; }

 private:
  const VulkanDevice& device_;
  std::vector<std::unique_ptr<DeviceImage>> colours_;
  DeviceImage depth_;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
