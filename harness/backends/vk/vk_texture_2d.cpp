#include "backends/vk/vk_texture_2d.h"

#include <cstring>

#include "backends/vk/vk_sampled_image.h"

namespace snell::vk {

namespace {

constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkDeviceSize kTexelBytes = 4 * sizeof(float);

VkImageCreateInfo imageInfo(const VulkanDevice& device, const Image& image) {
  requireSampledFormat(device, kFormat, "VK_FORMAT_R32G32B32A32_SFLOAT", true, "2D texture");
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = kFormat;
  info.extent = {static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height),
                 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  return info;
}

}  // namespace

Texture2D::Texture2D(const VulkanDevice& device, const Image& image, OneTimeCommands& commands,
                     HostBuffer& staging)
    : device_(device),
      image_(device, imageInfo(device, image), VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT) {
  sampler_ = makeBaseLevelSampler(device_, VK_FILTER_LINEAR, VK_SAMPLER_ADDRESS_MODE_REPEAT);
  try {
    upload(image, commands, staging);
  } catch (...) {
    vkDestroySampler(device_.handle(), sampler_, nullptr);
    throw;
  }
}

Texture2D::~Texture2D() { vkDestroySampler(device_.handle(), sampler_, nullptr); }

void Texture2D::upload(const Image& image, OneTimeCommands& commands, HostBuffer& staging) {
  const auto width = static_cast<std::uint32_t>(image.width);
  const auto height = static_cast<std::uint32_t>(image.height);
  const VkDeviceSize bytes = VkDeviceSize{width} * height * kTexelBytes;
  staging.reserve(bytes);
  // Image row j (image.at(i, j)) becomes texture row j, v in [j/height,
  // (j+1)/height]: the same texel as OpenGL's and the CPU reference's.
  std::memcpy(staging.data(), image.pixels.data(), bytes);
  VkBufferImageCopy region{};
  region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
  region.imageExtent = {width, height, 1};

  uploadToSampledImage(commands, staging, image_.image(), 1, {&region, 1}, "2D texture upload");
}

}  // namespace snell::vk
