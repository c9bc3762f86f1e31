#pragma once
// The colour and depth images of one render size, and their framebuffer.
// Made on the first render at that size and kept for the next.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "backends/vk/vk_device.h"
#include "backends/vk/vk_device_image.h"

namespace snell::vk {

class RenderTarget {
 public:
  // Throws SetupError when the device cannot render to the formats in vk_render_pass.h.
  RenderTarget(const VulkanDevice& device, VkRenderPass renderPass, std::uint32_t width,
               std::uint32_t height);
  ~RenderTarget();
  RenderTarget(const RenderTarget&) = delete;
  RenderTarget& operator=(const RenderTarget&) = delete;

  VkImage colourImage() const { return colour_.image(); }
  VkFramebuffer framebuffer() const { return framebuffer_; }

 private:
  const VulkanDevice& device_;
  DeviceImage colour_;
  DeviceImage depth_;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
