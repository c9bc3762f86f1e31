#include "backends/vk/spirv_validate.h"

#include <spirv-tools/libspirv.hpp>

namespace snell::vk {

std::string validateSpirvForVulkan(std::span<const std::uint32_t> spirv) {
  // Vulkan 1.1 is the oldest target that accepts the SPIR-V 1.3 glslang emits here.
  spvtools::SpirvTools tools(SPV_ENV_VULKAN_1_1);
  std::string messages;
  tools.SetMessageConsumer([&messages](spv_message_level_t, const char*,
                                       const spv_position_t& position, const char* message) {
    messages += "spirv-val: word " + std::to_string(position.index) + ": " + message + "\n";
  });
  if (tools.Validate(spirv.data(), spirv.size())) return {};
  return messages.empty() ? "spirv-val: module rejected without a message\n" : messages;
}

}  // namespace snell::vk
