#pragma once
// A CubeMap uploaded as a Vulkan cube image, with the sampler its filter
// asks for: base level only, clamped to the edge (cube sampling in Vulkan
// is always seamless, so the address mode only matters within a face).
#include <vulkan/vulkan.h>

#include "backends/vk/vk_device.h"
#include "backends/vk/vk_device_image.h"
#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"
#include "core/cube_map.h"

namespace snell::vk {

class CubeImage {
 public:
  // `map` must be well formed (see CubeImageCache). Uploads through
  // `staging` and waits for the upload. Throws SetupError when the device
  // cannot sample RGBA32F images the way the map's filter needs.
  CubeImage(const VulkanDevice& device, const CubeMap& map, OneTimeCommands& commands,
            HostBuffer& staging);
  ~CubeImage();
  CubeImage(const CubeImage&) = delete;
  CubeImage& operator=(const CubeImage&) = delete;

  VkImageView view() const { return image_.view(); }
  VkSampler sampler() const { return sampler_; }

 private:
  void upload(const CubeMap& map, OneTimeCommands& commands, HostBuffer& staging);

  const VulkanDevice& device_;
  DeviceImage image_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
