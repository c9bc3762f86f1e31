#pragma once
// One reusable command buffer and its fence: record, submit, wait. Every
// backend call finishes its GPU work before it returns, so one of each is
// all a runner needs.
#include <vulkan/vulkan.h>

#include "backends/vk/vk_device.h"

namespace snell::vk {

class OneTimeCommands {
 public:
  explicit OneTimeCommands(const VulkanDevice& device);
  ~OneTimeCommands();
  OneTimeCommands(const OneTimeCommands&) = delete;
  OneTimeCommands& operator=(const OneTimeCommands&) = delete;

  // Resets the command buffer and begins recording into it.
  VkCommandBuffer begin();

  // Ends recording, submits, and waits; `what` ("render", "capture") names
  // the work in the error when it does not finish.
  void submitAndWait(const char* what);

 private:
  void destroy();

  const VulkanDevice& device_;
  VkCommandPool pool_ = VK_NULL_HANDLE;
  VkCommandBuffer commands_ = VK_NULL_HANDLE;
  VkFence fence_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
