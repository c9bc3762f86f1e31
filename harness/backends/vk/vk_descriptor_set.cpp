#include "backends/vk/vk_descriptor_set.h"

#include <map>

#include "backends/vk/vk_check.h"

namespace snell::vk {

ProgramDescriptorSet::ProgramDescriptorSet(
    const VulkanDevice& device, const std::vector<VkDescriptorSetLayoutBinding>& bindings)
    : device_(device) {
  // A constructor that throws runs no destructor; clean up what was made so far.
  try {
    const VkDevice handle = device_.handle();
    if (!bindings.empty()) {
      VkDescriptorSetLayoutCreateInfo setInfo{};
      setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
      setInfo.bindingCount = static_cast<std::uint32_t>(bindings.size());
      setInfo.pBindings = bindings.data();
      check(vkCreateDescriptorSetLayout(handle, &setInfo, nullptr, &setLayout_),
            "vkCreateDescriptorSetLayout");

      std::map<VkDescriptorType, std::uint32_t> counts;
      for (const VkDescriptorSetLayoutBinding& binding : bindings)
        counts[binding.descriptorType] += binding.descriptorCount;
      std::vector<VkDescriptorPoolSize> sizes;
      for (const auto& [type, count] : counts) sizes.push_back({type, count});
      VkDescriptorPoolCreateInfo poolInfo{};
      poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
      poolInfo.maxSets = 1;
      poolInfo.poolSizeCount = static_cast<std::uint32_t>(sizes.size());
      poolInfo.pPoolSizes = sizes.data();
      check(vkCreateDescriptorPool(handle, &poolInfo, nullptr, &pool_), "vkCreateDescriptorPool");
      VkDescriptorSetAllocateInfo allocation{};
      allocation.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
      allocation.descriptorPool = pool_;
      allocation.descriptorSetCount = 1;
      allocation.pSetLayouts = &setLayout_;
      check(vkAllocateDescriptorSets(handle, &allocation, &set_), "vkAllocateDescriptorSets");
    }
    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = setLayout_ ? 1 : 0;
    layoutInfo.pSetLayouts = &setLayout_;
    check(vkCreatePipelineLayout(handle, &layoutInfo, nullptr, &pipelineLayout_),
          "vkCreatePipelineLayout");
  } catch (...) {
    destroy();
    throw;
  }
}

ProgramDescriptorSet::~ProgramDescriptorSet() { destroy(); }

void ProgramDescriptorSet::destroy() {
  const VkDevice handle = device_.handle();
  if (pipelineLayout_) vkDestroyPipelineLayout(handle, pipelineLayout_, nullptr);
  if (pool_) vkDestroyDescriptorPool(handle, pool_, nullptr);
  if (setLayout_) vkDestroyDescriptorSetLayout(handle, setLayout_, nullptr);
  pipelineLayout_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
  set_ = VK_NULL_HANDLE;
}

void ProgramDescriptorSet::writeUniformBuffer(std::uint32_t binding, VkBuffer buffer,
                                              VkDeviceSize bytes) const {
  VkDescriptorBufferInfo info{buffer, 0, bytes};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set_;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  write.pBufferInfo = &info;
  vkUpdateDescriptorSets(device_.handle(), 1, &write, 0, nullptr);
}

void ProgramDescriptorSet::writeSampledImage(std::uint32_t binding, VkSampler sampler,
                                             VkImageView view) const {
  VkDescriptorImageInfo info{sampler, view, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL};
  VkWriteDescriptorSet write{};
  write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
  write.dstSet = set_;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
  write.pImageInfo = &info;
  vkUpdateDescriptorSets(device_.handle(), 1, &write, 0, nullptr);
}

}  // namespace snell::vk
