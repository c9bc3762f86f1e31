#include "backends/vk/vk_sampled_image_upload.h"

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
  const VkImageMemoryBarrier toShader =
      layoutChange(image, layers, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, VK_ACCESS_TRANSFER_WRITE_BIT,
                   VK_ACCESS_SHADER_READ_BIT);
  vkCmdPipelineBarrier(recording, VK_PIPELINE_STAGE_TRANSFER_BIT,
                       VK_PIPELINE_STAGE_VERTEX_SHADER_BIT | VK_PIPELINE_STAGE_FRAGMENT_SHADER_BIT,
                       0, 0, nullptr, 0, nullptr, 1, &toShader);
  commands.submitAndWait(what);
}

}  // namespace snell::vk
