#include "backends/vk/vk_shader_module.h"

#include "backends/vk/vk_check.h"

namespace snell::vk {

ShaderModule::ShaderModule(const VulkanDevice& device, std::span<const std::uint32_t> spirv)
    : device_(device) {
  VkShaderModuleCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO;
  info.codeSize = spirv.size_bytes();
  info.pCode = spirv.data();
  check(vkCreateShaderModule(device_.handle(), &info, nullptr, &module_), "vkCreateShaderModule");
}

ShaderModule::~ShaderModule() { vkDestroyShaderModule(device_.handle(), module_, nullptr); }

}  // namespace snell::vk
