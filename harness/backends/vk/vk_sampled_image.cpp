#include "backends/vk/vk_sampled_image.h"

#include <string>

#include "backends/vk/vk_check.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

VkImageMemoryBarrier layoutChange(VkImage image, std::uint32_t layers, VkImageLayout from,
                                  VkImageLayout to, VkAccessFlags srcAccess,
                                  VkAccessFlags dstAccess) {
  VkImageMemoryBarrier barrier{};
  barrier.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER;
  barrier.srcAccessMask = srcAccess;
  barrier.dstAccessMask = dstAccess;
  barrier.oldLayout = from;
  barrier.newLayout = to;
  barrier.srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED;
  barrier.image = image;
  barrier.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
  return barrier;
}

}  // namespace

void requireSampledFormat(const VulkanDevice& device, VkFormat format, const char* formatName,
                          bool linear, const char* what) {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(device.physical(), format, &properties);
  const VkFormatFeatureFlags features = properties.optimalTilingFeatures;
  const std::string renderer = device.driverInfo().renderer;
  if ((features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) == 0 ||
      (features & VK_FORMAT_FEATURE_TRANSFER_DST_BIT) == 0)
    throw SetupError(renderer + " cannot sample " + formatName + " images");
  if (linear && (features & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) == 0)
    throw SetupError(renderer + " lacks VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT for " +
                     formatName + ", so it cannot filter a float " + what + " linearly");
}

VkSampler makeBaseLevelSampler(const VulkanDevice& device, VkFilter filter,
                               VkSamplerAddressMode addressing) {
  VkSamplerCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO;
  info.magFilter = filter;
  info.minFilter = filter;
  info.mipmapMode = VK_SAMPLER_MIPMAP_MODE_NEAREST;
  info.addressModeU = addressing;
  info.addressModeV = addressing;
  info.addressModeW = addressing;
  info.minLod = 0.0f;
  info.maxLod = 0.0f;
  info.borderColor = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
  VkSampler sampler = VK_NULL_HANDLE;
  check(vkCreateSampler(device.handle(), &info, nullptr, &sampler), "vkCreateSampler");
  return sampler;
}

void uploadToSampledImage(OneTimeCommands& commands, const HostBuffer& staging, VkImage image,
                          std::uint32_t layers, std::span<const VkBufferImageCopy> regions,
                          const char* what) {
  const VkCommandBuffer recording = commands.begin();
  const VkImageMemoryBarrier toTransfer =
      layoutChange(image, layers, VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   0, VK_ACCESS_TRANSFER_WRITE_BIT);
  vkCmdPipelineBarrier(recording, VK_PIPELINE_STAGE_TOP_OF_PIPE_BIT, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       0, 0, nullptr, 0, nullptr, 1, &toTransfer);
  vkCmdCopyBufferToImage(recording, staging.handle(), image, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                         static_cast<std::uint32_t>(regions.size()), regions.data());
  // Later submissions on the queue are in this barrier's second scope, so
  // every render that samples the image waits for the copy.
  const VkImageMemoryBarrier toShader = layoutChange(
      image, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL,
      VK_ACCESS_TRANSFER_WRITE_BIT, VK_ACCESS_SHADER_READ_BIT);
  vkCmdPipelineBarrier(recording, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                       0, 0, nullptr, 0, nullptr, 1, &toShader);
  commands.submitAndWait(what);
}

}  // namespace snell::vk
