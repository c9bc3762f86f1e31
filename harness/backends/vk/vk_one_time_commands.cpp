#include "backends/vk/vk_one_time_commands.h"

#include <string>

#include "backends/vk/vk_check.h"
#include "core/errors.h"

namespace snell::vk {

namespace {
// llvmpipe JITs a new pipeline on its first draw (~0.1 s); a minute means a hang.
constexpr std::uint64_t kFenceTimeoutNs = 60ull * 1000 * 1000 * 1000;
}  // namespace

OneTimeCommands::OneTimeCommands(const VulkanDevice& device) : device_(device) {
  try {
    const VkDevice handle = device_.handle();
    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = device_.queueFamily();
    check(vkCreateCommandPool(handle, &poolInfo, nullptr, &pool_), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo allocation{};
    allocation.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocation.commandPool = pool_;
    allocation.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocation.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(handle, &allocation, &commands_), "vkAllocateCommandBuffers");
    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    check(vkCreateFence(handle, &fenceInfo, nullptr, &fence_), "vkCreateFence");
  } catch (...) {
    destroy();
    throw;
  }
}

OneTimeCommands::~OneTimeCommands() { destroy(); }

void OneTimeCommands::destroy() {
  const VkDevice handle = device_.handle();
  vkDeviceWaitIdle(handle);
  if (fence_) vkDestroyFence(handle, fence_, nullptr);
  if (pool_) vkDestroyCommandPool(handle, pool_, nullptr);
  fence_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  commands_ = VK_NULL_HANDLE;
}

VkCommandBuffer OneTimeCommands::begin() {
  check(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo info{};
  info.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  info.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commands_, &info), "vkBeginCommandBuffer");
  return commands_;
}

void OneTimeCommands::submitAndWait(const char* what) {
  check(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");
  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  check(vkQueueSubmit(device_.queue(), 1, &submit, fence_), "vkQueueSubmit");
  const VkResult waited = vkWaitForFences(device_.handle(), 1, &fence_, VK_TRUE, kFenceTimeoutNs);
  if (waited == VK_TIMEOUT)
    throw SetupError(std::string("the Vulkan ") + what + " did not finish within 60 s");
  check(waited, "vkWaitForFences");
  check(vkResetFences(device_.handle(), 1, &fence_), "vkResetFences");
}

}  // namespace snell::vk
