#pragma once
// The Vulkan objects that draw with one linked program: both shader
// modules, the descriptor set its descriptors are bound through, and one
// pipeline per (vertex input layout, culling) pair.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <map>
#include <span>
#include <utility>
#include <vector>

#include "backends/vk/program_descriptors.h"
#include "backends/vk/vk_descriptor_set.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_shader_module.h"
#include "backends/vk/vk_vertex_input.h"

namespace snell::vk {

class RenderPipelines {
 public:
  // `descriptors` lists only uniform buffers and combined image samplers,
  // as bindProgramDescriptors found them in these very modules.
  RenderPipelines(const VulkanDevice& device, VkRenderPass renderPass, std::uint32_t colourTargets,
                  std::span<const std::uint32_t> vertexSpirv,
                  std::span<const std::uint32_t> fragmentSpirv,
                  const std::vector<ProgramDescriptor>& descriptors);
  ~RenderPipelines();
  RenderPipelines(const RenderPipelines&) = delete;
  RenderPipelines& operator=(const RenderPipelines&) = delete;

  // Built on first use for each combination, then reused.
  VkPipeline pipeline(const std::vector<VertexInputFormat>& inputs, bool cullBackFaces);
  const ProgramDescriptorSet& descriptors() const { return descriptors_; }

 private:
  const VulkanDevice& device_;
  VkRenderPass renderPass_;
  std::uint32_t colourTargets_;
  ShaderModule vertex_;
  ShaderModule fragment_;
  ProgramDescriptorSet descriptors_;
  std::map<std::pair<std::vector<VertexInputFormat>, bool>, VkPipeline> pipelines_;
};

}  // namespace snell::vk
