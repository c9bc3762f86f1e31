#pragma once
// An Image uploaded as a Vulkan 2D image, with the sampler that
// RenderJob::textures2D promises: base level only, LINEAR filtering, REPEAT
// wrapping in u and v, as OpenGL's GlTextures2D and the CPU reference
// (oracle/reference/texture_2d_sampling.h) sample.
#include <vulkan/vulkan.h>

#include "backends/vk/vk_device.h"
#include "backends/vk/vk_device_image.h"
#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"
#include "core/image.h"

namespace snell::vk {

class Texture2D {
 public:
  // `image` must be well formed (see Texture2DCache). Uploads through
  // `staging` and waits for the upload. Throws SetupError when the device
  // cannot sample RGBA32F images linearly.
  Texture2D(const VulkanDevice& device, const Image& image, OneTimeCommands& commands,
            HostBuffer& staging);
  ~Texture2D();
  Texture2D(const Texture2D&) = delete;
  Texture2D& operator=(const Texture2D&) = delete;

  VkImageView view() const { return image_.view(); }
  VkSampler sampler() const { return sampler_; }

 private:
  void upload(const Image& image, OneTimeCommands& commands, HostBuffer& staging);

  const VulkanDevice& device_;
  DeviceImage image_;
  VkSampler sampler_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
