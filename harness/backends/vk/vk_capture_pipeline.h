#pragma once
// The Vulkan objects that run one compiled vertex shader for capture: its
// shader module, a descriptor set for gl_DefaultUniformBlock, and one
// vertex-only, rasterizer-discard pipeline per vertex input layout.
#include <vulkan/vulkan.h>

#include <compare>
#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "backends/vk/vk_device.h"

namespace snell::vk {

// One vertex buffer binding per shader input.
struct VertexInputFormat {
  std::uint32_t location = 0;
  std::uint32_t components =
      4;  // fp32 components the stream supplies; Vulkan fills the rest with (0, 0, 1)
  bool constant = false;  // one value for every vertex (stride 0)
  auto operator<=>(const VertexInputFormat&) const = default;
};

struct UniformBinding {
  std::uint32_t set = 0;
  std::uint32_t binding = 0;
};

class CapturePipelines {
 public:
  // `vertexSpirv` already carries the transform feedback decorations.
  CapturePipelines(const VulkanDevice& device, VkRenderPass renderPass,
                   std::span<const std::uint32_t> vertexSpirv,
                   std::optional<UniformBinding> uniformBlock);
  ~CapturePipelines();
  CapturePipelines(const CapturePipelines&) = delete;
  CapturePipelines& operator=(const CapturePipelines&) = delete;

  // Built on first use for each layout, then reused.
  VkPipeline pipeline(const std::vector<VertexInputFormat>& inputs);
  VkPipelineLayout layout() const { return layout_; }
  VkDescriptorSet descriptorSet() const { return descriptorSet_; }  // null without a uniform block
  std::optional<UniformBinding> uniformBinding() const { return uniformBinding_; }

 private:
  void destroy();

  const VulkanDevice& device_;
  VkRenderPass renderPass_;
  std::optional<UniformBinding> uniformBinding_;
  VkShaderModule module_ = VK_NULL_HANDLE;
  VkDescriptorSetLayout setLayout_ = VK_NULL_HANDLE;
  VkPipelineLayout layout_ = VK_NULL_HANDLE;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;
  VkDescriptorSet descriptorSet_ = VK_NULL_HANDLE;
  std::map<std::vector<VertexInputFormat>, VkPipeline> pipelines_;
};

}  // namespace snell::vk
