#include "backends/vk/vk_capture_pipeline.h"

#include <string>

#include "backends/vk/vk_check.h"
#include "core/errors.h"
#include "core/phase_clock.h"

namespace snell::vk {

namespace {

std::vector<VkDescriptorSetLayoutBinding> layoutBindings(
    std::optional<UniformBinding> uniformBlock) {
  if (!uniformBlock) return {};
  if (uniformBlock->set != 0) {
    throw SetupError("gl_DefaultUniformBlock is in descriptor set " +
                     std::to_string(uniformBlock->set) + "; the capture pipeline expects set 0");
  }
  VkDescriptorSetLayoutBinding binding{};
  binding.binding = uniformBlock->binding;
  binding.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
  binding.descriptorCount = 1;
  binding.stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
  return {binding};
}

}  // namespace

CapturePipelines::CapturePipelines(const VulkanDevice& device, VkRenderPass renderPass,
                                   std::span<const std::uint32_t> vertexSpirv,
                                   std::optional<UniformBinding> uniformBlock)
    : device_(device),
      renderPass_(renderPass),
      uniformBinding_(uniformBlock),
      module_(device, vertexSpirv),
      descriptors_(device, layoutBindings(uniformBlock)) {}

CapturePipelines::~CapturePipelines() {
  for (auto& [inputs, pipeline] : pipelines_)
    vkDestroyPipeline(device_.handle(), pipeline, nullptr);
}

VkPipeline CapturePipelines::pipeline(const std::vector<VertexInputFormat>& inputs) {
  if (auto found = pipelines_.find(inputs); found != pipelines_.end()) return found->second;

  // A new vertex input layout is a pipeline to create (lavapipe compiles
  // its shaders here): the compile phase's, as the program's own.
  const PhaseScope phase(Phase::Compile);
  const VertexInputDescription vertexInput(inputs);

  // Triangles, not points: with validation on, a point list needs the
  // shader to write PointSize, which published listings do not.
  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.rasterizerDiscardEnable = VK_TRUE;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = VK_CULL_MODE_NONE;
  raster.lineWidth = 1.0f;

  VkPipelineShaderStageCreateInfo stage{};
  stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
  stage.stage = VK_SHADER_STAGE_VERTEX_BIT;
  stage.module = module_.handle();
  stage.pName = "main";

  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = 1;
  info.pStages = &stage;
  info.pVertexInputState = &vertexInput.state();
  info.pInputAssemblyState = &assembly;
  info.pRasterizationState = &raster;
  info.layout = descriptors_.pipelineLayout();
  info.renderPass = renderPass_;
  info.subpass = 0;

  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(device_.handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");
  pipelines_.emplace(inputs, pipeline);
  return pipeline;
}

}  // namespace snell::vk
