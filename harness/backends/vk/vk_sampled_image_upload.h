#pragma once
// The one way texels reach a sampled image (cube maps, 2D textures): copy
// the staged bytes into the image's layers and leave it in
// SHADER_READ_ONLY_OPTIMAL, behind a barrier that makes every later render
// on the queue wait for the copy. Submits and waits.
#include <vulkan/vulkan.h>

#include <cstdint>
#include <span>

#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"

namespace snell::vk {

// `regions` say where each layer's texels are in `staging`; `layers` is the
// image's layer count (6 for a cube map); `what` names the upload in errors.
void uploadToSampledImage(OneTimeCommands& commands, const HostBuffer& staging, VkImage image,
                          std::uint32_t layers, std::span<const VkBufferImageCopy> regions,
                          const char* what);

}  // namespace snell::vk
