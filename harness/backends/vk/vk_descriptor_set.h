#pragma once
// The pipeline layout of one program, with its single descriptor set (set
// 0) and the pool it comes from. Every backend call waits for its GPU work
// before returning, so one set, rewritten before each draw, is enough.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <vector>

#include "backends/vk/vk_device.h"

namespace snell::vk {

class ProgramDescriptorSet {
 public:
  // No bindings: a pipeline layout with no sets, and set() is null.
  ProgramDescriptorSet(const VulkanDevice& device,
                       const std::vector<VkDescriptorSetLayoutBinding>& bindings);
  ~ProgramDescriptorSet();
  ProgramDescriptorSet(const ProgramDescriptorSet&) = delete;
  ProgramDescriptorSet& operator=(const ProgramDescriptorSet&) = delete;

  VkPipelineLayout pipelineLayout() const { return pipelineLayout_; }
  VkDescriptorSet set() const { return set_; }

  void writeUniformBuffer(std::uint32_t binding, VkBuffer buffer, VkDeviceSize bytes) const;
  void writeSampledImage(std::uint32_t binding, VkSampler sampler, VkImageView view) const;

 private:
  void destroy();

  const VulkanDevice& device_;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  VkPipelineLayout pipelineLayout_ = VK_NULL_HANDLE;
};

}  // namespace snell::vk
