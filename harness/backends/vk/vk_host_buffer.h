#pragma once
// A persistently mapped, host-coherent buffer that grows on demand, so that
// thousands of small captures reuse one allocation instead of making their own.
#include <vulkan/vulkan.h>

#include <cstddef>

#include "backends/vk/vk_device.h"

namespace snell::vk {

class HostBuffer {
 public:
  // `preferred` memory properties (HOST_CACHED for read-back) are used when the device has them.
  HostBuffer(const VulkanDevice& device, VkBufferUsageFlags usage, VkMemoryPropertyFlags preferred);
  ~HostBuffer();
  HostBuffer(const HostBuffer&) = delete;
  HostBuffer& operator=(const HostBuffer&) = delete;

  // Makes room for `bytes`; the contents are lost when it has to grow. Only
  // call while no submitted work uses the buffer.
  void reserve(VkDeviceSize bytes);

  VkBuffer handle() const { return buffer_; }
  std::byte* data() const { return mapped_; }
  VkDeviceSize capacity() const { return capacity_; }

 private:
  void release();

  const VulkanDevice& device_;
  VkBufferUsageFlags usage_;
  VkMemoryPropertyFlags preferred_;
  VkBuffer buffer_ = VK_NULL_HANDLE;
  VkDeviceMemory memory_ = VK_NULL_HANDLE;
  std::byte* mapped_ = nullptr;
  VkDeviceSize capacity_ = 0;
};

}  // namespace snell::vk
