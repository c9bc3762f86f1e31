#include "backends/vk/vk_device_image.h"

#include "backends/vk/vk_check.h"

namespace snell::vk {

DeviceImage::DeviceImage(const VulkanDevice& device, const VkImageCreateInfo& info,
                         VkImageViewType viewType, VkImageAspectFlags aspect)
    : device_(device) {
  try {
    const VkDevice handle = device_.handle();
    check(vkCreateImage(handle, &info, nullptr, &image_), "vkCreateImage");
    VkMemoryRequirements requirements{};
    vkGetImageMemoryRequirements(handle, image_, &requirements);
    VkMemoryAllocateInfo allocation{};
    allocation.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO;
    allocation.allocationSize = requirements.size;
    allocation.memoryTypeIndex =
        device_.memoryType(requirements.memoryTypeBits, 0, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
    check(vkAllocateMemory(handle, &allocation, nullptr, &memory_), "vkAllocateMemory");
    check(vkBindImageMemory(handle, image_, memory_, 0), "vkBindImageMemory");

    VkImageViewCreateInfo viewInfo{};
    viewInfo.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO;
    viewInfo.image = image_;
    viewInfo.viewType = viewType;
    viewInfo.format = info.format;
    viewInfo.subresourceRange = {aspect, 0, info.mipLevels, 0, info.arrayLayers};
    check(vkCreateImageView(handle, &viewInfo, nullptr, &view_), "vkCreateImageView");
  } catch (...) {
    destroy();
    throw;
  }
}

DeviceImage::~DeviceImage() { destroy(); }

void DeviceImage::destroy() {
  const VkDevice handle = device_.handle();
  if (view_) vkDestroyImageView(handle, view_, nullptr);
  if (image_) vkDestroyImage(handle, image_, nullptr);
  if (memory_) vkFreeMemory(handle, memory_, nullptr);
  view_ = VK_NULL_HANDLE;
  image_ = VK_NULL_HANDLE;
  memory_ = VK_NULL_HANDLE;
}

}  // namespace snell::vk
