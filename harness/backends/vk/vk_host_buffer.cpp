#include "backends/vk/vk_host_buffer.h"

#include <algorithm>

#include "backends/vk/vk_check.h"

namespace snell::vk {

HostBuffer::HostBuffer(const VulkanDevice& device, VkBufferUsageFlags usage,
                       VkMemoryPropertyFlags preferred)
    : device_(device), usage_(usage), preferred_(preferred) {}

HostBuffer::~HostBuffer() { release(); }

void HostBuffer::release() {
  if (mapped_) vkUnmapMemory(device_.handle(), memory_);
  if (memory_) vkFreeMemory(device_.handle(), memory_, nullptr);
  if (buffer_) vkDestroyBuffer(device_.handle(), buffer_, nullptr);
  buffer_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
  mapped_ = nullptr;
  capacity_ = 0;
}

void HostBuffer::reserve(VkDeviceSize bytes) {
  if (bytes <= capacity_) return;
  // Doubling keeps a slowly growing workload from reallocating on every call.
  const VkDeviceSize size = std::max<VkDeviceSize>({bytes, capacity_ * 2, 4096});
  release();

  VkBufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO;
  info.size = size;
  info.usage = usage_;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  check(vkCreateBuffer(device_.handle(), &info, nullptr, &buffer_), "vkCreateBuffer");

  VkMemoryRequirements requirements{};
  vkGetBufferMemoryRequirements(device_.handle(), buffer_, &requirements);
  VkMemoryAllocateInfo allocation{};
  allocation.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
  allocation.allocationSize = requirements.size;
  // Host-coherent memory needs no flush or invalidate around the fence wait.
  allocation.memoryTypeIndex = device_.memoryType(
      requirements.memoryTypeBits,
      VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT, preferred_);
  check(vkAllocateMemory(device_.handle(), &allocation, nullptr, &memory_), "vkAllocateMemory");
  check(vkBindBufferMemory(device_.handle(), buffer_, memory_, 0), "vkBindBufferMemory");
  void* mapped = nullptr;
  check(vkMapMemory(device_.handle(), memory_, 0, VK_WHOLE_SIZE, 0, &mapped), "vkMapMemory");
  mapped_ = static_cast<std::byte*>(mapped);
  capacity_ = size;
}

}  // namespace snell::vk
