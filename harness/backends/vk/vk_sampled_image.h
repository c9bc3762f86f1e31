#pragma once
// What the sampled images (cube maps, 2D textures) share: the check that
// the device can sample and filter their float format, their base-level
// sampler, and the one way texels reach them.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "backends/vk/vk_device.h"
#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"

namespace snell::vk {

// Throws SetupError naming the renderer when it cannot sample `format`
// images (or, with `linear`, filter them linearly); `what` names the kind
// ("cube map", "2D texture") in the message.
void requireSampledFormat(const VulkanDevice& device, VkFormat format, const char* formatName,
                          bool linear, const char* what);

// A sampler of the base level only, with this filter and addressing; the
// caller destroys it.
VkSampler makeBaseLevelSampler(const VulkanDevice& device, VkFilter filter,
                               VkSamplerAddressMode addressing);

// Copies the staged bytes into the image's layers and leaves it in
// SHADER_READ_ONLY_OPTIMAL, behind a barrier that makes every later render
// on the queue wait for the copy. Submits and waits.
// `regions` say where each layer's texels are in `staging`; `layers` is the
// image's layer count (6 for a cube map); `what` names the upload in errors.
void uploadToSampledImage(OneTimeCommands& commands, const HostBuffer& staging, VkImage image,
                          std::uint32_t layers, std::span<const VkBufferImageCopy> regions,
                          const char* what);

}  // namespace snell::vk
