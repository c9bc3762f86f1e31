#pragma once
// The Vulkan objects that run one compiled vertex shader for capture: its
// shader module, a descriptor set for gl_DefaultUniformBlock, and one
// vertex-only, rasterizer-discard pipeline per vertex input layout.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <optional>
#include <span>
#include <vector>

#include "backends/vk/vk_descriptor_set.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_shader_module.h"
#include "backends/vk/vk_vertex_input.h"

namespace snell::vk {

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
  const ProgramDescriptorSet& descriptors() const { return descriptors_; }
  std::optional<UniformBinding> uniformBinding() const { return uniformBinding_; }

 private:
  const VulkanDevice& device_;
  VkRenderPass renderPass_;
  std::optional<UniformBinding> uniformBinding_;
  ShaderModule module_;
  ProgramDescriptorSet descriptors_;
  std::map<std::vector<VertexInputFormat>, VkPipeline> pipelines_;
};

}  // namespace snell::vk
