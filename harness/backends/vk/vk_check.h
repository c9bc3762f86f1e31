#pragma once
// Turns a failed Vulkan call into a SetupError that names the call and the
// result, so that a failure on an unfamiliar driver reads as a sentence.
#include <vulkan/vulkan.h>

#include <string>

namespace snell::vk {

std::string resultName(VkResult result);

// Throws SetupError("<call> failed: <result>") unless result is VK_SUCCESS.
void check(VkResult result, const char* call);

}  // namespace snell::vk
