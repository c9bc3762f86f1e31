#pragma once
// An image in its own device memory (device-local where the device has
// any), with one view over all its layers.
#include <vulkan/vulkan.h>

#include "backends/vk/vk_device.h"

namespace snell::vk {

class DeviceImage {
 public:
  DeviceImage(const VulkanDevice& device, const VkImageCreateInfo& info, VkImageViewType viewType,
              VkImageAspectFlags aspect);
  ~DeviceImage();
  DeviceImage(const DeviceImage&) = delete;
  DeviceImage& operator=(const DeviceImage&) = delete;

  VkImage image() const { return image_; }
  VkImageView view() const { return view_; }

 private:
  void destroy();

  const VulkanDevice& device_;
  VkImage image_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  VkImageView view_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
