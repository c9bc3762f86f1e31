#pragma once
#include <string>
#include <vector>
// The one logical device a backend uses: the first physical device with
// VK_EXT_transform_feedback, a graphics queue, and what the capture code
// needs to know about it.
#include <vulkan/vulkan.h>

#include <cstdint>

#include "backends/backend.h"
#include "backends/vk/vk_instance.h"

namespace snell::vk {

struct TransformFeedbackCommands {
  PFN_vkCmdBindTransformFeedbackBuffersEXT bindBuffers = nullptr;
  PFN_vkCmdBeginTransformFeedbackEXT begin = nullptr;
  PFN_vkCmdEndTransformFeedbackEXT end = nullptr;
};

struct PhysicalDeviceSummary {
  int index = 0;
  std::string name;    // deviceName
  std::string detail;  // type, driver, API version, vendor:device id, what it lacks
};

// Every physical device every installed ICD offers (VK_DRIVER_FILES as set).
std::vector<PhysicalDeviceSummary> listPhysicalDevices();

class VulkanDevice {
 public:
  // `wanted`: a physical device by index, vendor:device id (hex) or a part
  // of its name; "gpu" the first that is not a CPU; "" the first usable.
  // Throws SetupError naming the devices seen and what each one lacks.
  VulkanDevice(const VulkanInstance& instance, const std::string& wanted);
  ~VulkanDevice();
  VulkanDevice(const VulkanDevice&) = delete;
  VulkanDevice& operator=(const VulkanDevice&) = delete;

  VkDevice handle() const { return device_; }
  VkPhysicalDevice physical() const { return physical_; }
  VkQueue queue() const { return queue_; }
  std::uint32_t queueFamily() const { return queueFamily_; }
  const DriverInfo& driverInfo() const { return driverInfo_; }
  const TransformFeedbackCommands& transformFeedback() const { return xfb_; }
  std::uint32_t maxTransformFeedbackStride() const { return maxXfbStride_; }
  const VkPhysicalDeviceLimits& limits() const { return limits_; }

  // A memory type in `typeBits` with all of `required`, preferring one that
  // also has `preferred`. Throws SetupError when there is none.
  std::uint32_t memoryType(std::uint32_t typeBits, VkMemoryPropertyFlags required,
                           VkMemoryPropertyFlags preferred) const;

 private:
  VkPhysicalDevice physical_ = VK_NULL_HANDLE;
  VkDevice device_ = VK_NULL_HANDLE;
  VkQueue queue_ = VK_NULL_HANDLE;
  std::uint32_t queueFamily_ = 0;
  DriverInfo driverInfo_;
  TransformFeedbackCommands xfb_;
  std::uint32_t maxXfbStride_ = 0;
  VkPhysicalDeviceLimits limits_{};
  VkPhysicalDeviceMemoryProperties memory_{};
};

}  // namespace snell::vk
