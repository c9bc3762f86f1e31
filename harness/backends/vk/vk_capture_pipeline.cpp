#include "backends/vk/vk_capture_pipeline.h"

#include "backends/vk/vk_check.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

VkFormat floatFormat(std::uint32_t components) {
  switch (components) {
    case 1:
      return VK_FORMAT_R32_SFLOAT;
    case 2:
      return VK_FORMAT_R32G32_SFLOAT;
    case 3:
      return VK_FORMAT_R32G32B32_SFLOAT;
    default:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
}

}  // namespace

CapturePipelines::CapturePipelines(const VulkanDevice& device, VkRenderPass renderPass,
                                   std::span<const std::uint32_t> vertexSpirv,
                                   std::optional<UniformBinding> uniformBlock)
    : device_(device), renderPass_(renderPass), uniformBinding_(uniformBlock) {
  // A constructor that throws runs no destructor; clean up what was made so far.
  try {
    VkShaderModuleCreateInfo moduleInfo{};
    moduleInfo.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
    moduleInfo.codeSize = vertexSpirv.size_bytes();
    moduleInfo.pCode = vertexSpirv.data();
    check(vkCreateShaderModule(device_.handle(), &moduleInfo, nullptr, &module_),
          "vkCreateShaderModule");

    std::vector<VkDescriptorSetLayout> setLayouts;
    if (uniformBlock) {
      if (uniformBlock->set != 0) {
        throw SetupError("gl_DefaultUniformBlock is in descriptor set " +
                         std::to_string(uniformBlock->set) +
                         "; the capture pipeline expects set 0");
      }
      VkDescriptorSetLayoutBinding binding{};
      binding.binding = uniformBlock->binding;
      binding.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
      binding.descriptorCount = 1;
      binding.stageFlags = VK_SHADER_STAGE_VERTEX_BIT;
      VkDescriptorSetLayoutCreateInfo setInfo{};
      setInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO;
      setInfo.bindingCount = 1;
      setInfo.pBindings = &binding;
      check(vkCreateDescriptorSetLayout(device_.handle(), &setInfo, nullptr, &setLayout_),
            "vkCreateDescriptorSetLayout");
      setLayouts.push_back(setLayout_);

      VkDescriptorPoolSize poolSize{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1};
      VkDescriptorPoolCreateInfo poolInfo{};
      poolInfo.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO;
      poolInfo.maxSets = 1;
      poolInfo.poolSizeCount = 1;
      poolInfo.pPoolSizes = &poolSize;
      check(vkCreateDescriptorPool(device_.handle(), &poolInfo, nullptr, &pool_),
            "vkCreateDescriptorPool");
      VkDescriptorSetAllocateInfo allocation{};
      allocation.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO;
      allocation.descriptorPool = pool_;
      allocation.descriptorSetCount = 1;
      allocation.pSetLayouts = &setLayout_;
      check(vkAllocateDescriptorSets(device_.handle(), &allocation, &descriptorSet_),
            "vkAllocateDescriptorSets");
    }

    VkPipelineLayoutCreateInfo layoutInfo{};
    layoutInfo.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO;
    layoutInfo.setLayoutCount = static_cast<std::uint32_t>(setLayouts.size());
    layoutInfo.pSetLayouts = setLayouts.data();
    check(vkCreatePipelineLayout(device_.handle(), &layoutInfo, nullptr, &layout_),
          "vkCreatePipelineLayout");
  } catch (...) {
    destroy();
    throw;
  }
}

CapturePipelines::~CapturePipelines() { destroy(); }

void CapturePipelines::destroy() {
  const VkDevice device = device_.handle();
  for (auto& [inputs, pipeline] : pipelines_) vkDestroyPipeline(device, pipeline, nullptr);
  pipelines_.clear();
  if (layout_) vkDestroyPipelineLayout(device, layout_, nullptr);
  if (pool_) vkDestroyDescriptorPool(device, pool_, nullptr);
  if (setLayout_) vkDestroyDescriptorSetLayout(device, setLayout_, nullptr);
  if (module_) vkDestroyShaderModule(device, module_, nullptr);
  layout_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
  setLayout_ = VK_NULL_HANDLE;
  module_ = VK_NULL_HANDLE;
}

VkPipeline CapturePipelines::pipeline(const std::vector<VertexInputFormat>& inputs) {
  if (auto found = pipelines_.find(inputs); found != pipelines_.end()) return found->second;

  std::vector<VkVertexInputBindingDescription> bindings;
  std::vector<VkVertexInputAttributeDescription> attributes;
  for (std::uint32_t i = 0; i < inputs.size(); ++i) {
    const VertexInputFormat& input = inputs[i];
    bindings.push_back(
        {i, input.constant ? 0u : input.components * 4u, VK_VERTEX_INPUT_RATE_VERTEX});
    attributes.push_back({input.location, i, floatFormat(input.components), 0});
  }
  VkPipelineVertexInputStateCreateInfo vertexInput{};
  vertexInput.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  vertexInput.vertexBindingDescriptionCount = static_cast<std::uint32_t>(bindings.size());
  vertexInput.pVertexBindingDescriptions = bindings.data();
  vertexInput.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(attributes.size());
  vertexInput.pVertexAttributeDescriptions = attributes.data();

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
  stage.module = module_;
  stage.pName = "main";

  VkGraphicsPipelineCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO;
  info.stageCount = 1;
  info.pStages = &stage;
  info.pVertexInputState = &vertexInput;
  info.pInputAssemblyState = &assembly;
  info.pRasterizationState = &raster;
  info.layout = layout_;
  info.renderPass = renderPass_;
  info.subpass = 0;

  VkPipeline pipeline = VK_NULL_HANDLE;
  check(vkCreateGraphicsPipelines(device_.handle(), VK_NULL_HANDLE, 1, &info, nullptr, &pipeline),
        "vkCreateGraphicsPipelines");
  pipelines_.emplace(inputs, pipeline);
  return pipeline;
}

}  // namespace snell::vk
