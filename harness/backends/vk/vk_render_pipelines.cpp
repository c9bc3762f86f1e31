#include "backends/vk/vk_render_pipelines.h"

#include "backends/vk/vk_check.h"
#include "core/phase_clock.h"

namespace snell::vk {

namespace {

std::vector<VkDescriptorSetLayoutBinding> layoutBindings(
    const std::vector<ProgramDescriptor>& descriptors) {
  std::vector<VkDescriptorSetLayoutBinding> bindings;
  for (const ProgramDescriptor& descriptor : descriptors) {
    VkDescriptorSetLayoutBinding binding{};
    binding.binding = descriptor.binding;
    binding.descriptorType = descriptor.kind == DescriptorKind::UniformBuffer
                                 ? VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER
                                 : VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    binding.descriptorCount = 1;
    if (descriptor.inVertexStage) binding.stageFlags |= VK_SHADER_STAGE_VERTEX_BIT;
    if (descriptor.inFragmentStage) binding.stageFlags |= VK_SHADER_STAGE_FRAGMENT_BIT;
    bindings.push_back(binding);
  }
  return bindings;
}

}  // namespace

RenderPipelines::RenderPipelines(const VulkanDevice& device, VkRenderPass renderPass,
                                 std::uint32_t colourTargets,
                                 std::span<const std::uint32_t> vertexSpirv,
                                 std::span<const std::uint32_t> fragmentSpirv,
                                 const std::vector<ProgramDescriptor>& descriptors)
    : device_(device),
      renderPass_(renderPass),
      colourTargets_(colourTargets),
      vertex_(device, vertexSpirv),
      fragment_(device, fragmentSpirv),
      descriptors_(device, layoutBindings(descriptors)) {}

RenderPipelines::~RenderPipelines() {
  for (auto& [key, pipeline] : pipelines_) vkDestroyPipeline(device_.handle(), pipeline, nullptr);
}

VkPipeline RenderPipelines::pipeline(const std::vector<VertexInputFormat>& inputs,
                                     bool cullBackFaces) {
  const auto key = std::make_pair(inputs, cullBackFaces);
  if (auto found = pipelines_.find(key); found != pipelines_.end()) return found->second;

  // A new vertex input layout is a pipeline to create (lavapipe compiles
  // its shaders here): the compile phase's, as the program's own.
  const PhaseScope phase(Phase::Compile);
  const VertexInputDescription vertexInput(inputs);

  VkPipelineInputAssemblyStateCreateInfo assembly{};
  assembly.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO;
  assembly.topology = VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;

  // Viewport and scissor are set per draw, so one pipeline serves every size.
  VkPipelineViewportStateCreateInfo viewport{};
  viewport.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO;
  viewport.viewportCount = 1;
  viewport.scissorCount = 1;
  const VkDynamicState dynamic[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
  VkPipelineDynamicStateCreateInfo dynamicState{};
  dynamicState.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO;
  dynamicState.dynamicStateCount = 2;
  dynamicState.pDynamicStates = dynamic;

  // The draw's viewport has a negative height, which puts clip-space +y at
  // the top as in OpenGL. That flip also mirrors every triangle's winding
  // in framebuffer space back to what OpenGL sees, so a triangle that is
  // counter-clockwise in OpenGL is counter-clockwise to Vulkan too.
  VkPipelineRasterizationStateCreateInfo raster{};
  raster.sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO;
  raster.polygonMode = VK_POLYGON_MODE_FILL;
  raster.cullMode = cullBackFaces ? VK_CULL_MODE_BACK_BIT : VK_CULL_MODE_NONE;
  raster.frontFace = VK_FRONT_FACE_COUNTER_CLOCKWISE;
  raster.lineWidth = 1.0f;

  VkPipelineMultisampleStateCreateInfo multisample{};
  multisample.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO;
  multisample.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;

  // Vulkan clips z to [0, w] where OpenGL clips to [-w, w] and maps NDC z
  // to depth differently; scenes keep every visible point at NDC z in
  // [0, 1], where neither API clips and both order depths the same way, so
  // no depth-range adaptation is needed.
  VkPipelineDepthStencilStateCreateInfo depth{};
  depth.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO;
  depth.depthTestEnable = VK_TRUE;
  depth.depthWriteEnable = VK_TRUE;
  depth.depthCompareOp = VK_COMPARE_OP_LESS;

  VkPipelineColorBlendAttachmentState colour{};
  colour.colorWriteMask = VK_COLOR_COMPONENT_R_BIT | VK_COLOR_COMPONENT_G_BIT |
                          VK_COLOR_COMPONENT_B_BIT | VK_COLOR_COMPONENT_A_BIT;
  const std::vector<VkPipelineColorBlendAttachmentState> colours(colourTargets_, colour);
  VkPipelineColorBlendStateCreateInfo blend{};
  blend.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO;
  blend.attachmentCount = colourTargets_;
  blend.pAttachments = colours.data();

  VkPipelineShaderStageCreateInfo stages[2]{};
  for (VkPipelineShaderStageCreateInfo& stage : stages) {
    stage.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO;
    stage.pName = "main";
  }
  stages[0].stage = VK_SHADER_STAGE_VERTEX_BIT;
  stages[0].module = vertex_.handle();
  stages[1].stage = VK_SHADER_STAGE_FRAGMENT_BIT;
  stages[1].module = fragment_.handle();

  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = 2;
  info.pStages = stages;
  info.pVertexInputState = &vertexInput.state();
  info.pInputAssemblyState = &assembly;
  info.pViewportState = &viewport;
  info.pRasterizationState = &raster;
  info.pMultisampleState = &multisample;
  info.pDepthStencilState = &depth;
  info.pColorBlendState = &blend;
  info.pDynamicState = &dynamicState;
  info.layout = descriptors_.pipelineLayout();
  info.renderPass = renderPass_;
  info.subpass = 0;

  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(device_.handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");
  pipelines_.emplace(key, pipeline);
  return pipeline;
}

}  // namespace snell::vk
