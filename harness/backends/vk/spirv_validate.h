#pragma once
// SPIRV-Tools' validator, run on every module the backend builds, so that a
// bad post-pass shows up as a readable message before the driver sees it.
#include <cstdint>
#include <span>
#include <string>

namespace snell::vk {

// Empty when the module is valid SPIR-V for Vulkan 1.1; otherwise the
// validator's messages, one per line.
std::string validateSpirvForVulkan(std::span<const std::uint32_t> spirv);

}  // namespace snell::vk
