#include "backends/vk/vk_cube_image.h"

#include <cstring>

#include "backends/vk/vk_sampled_image.h"

namespace snell::vk {

namespace {

constexpr VkFormat kCubeFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
constexpr VkDeviceSize kTexelBytes = 4 * sizeof(float);

VkImageCreateInfo cubeInfo(const VulkanDevice& device, const CubeMap& map) {
  requireSampledFormat(device, kCubeFormat, "VK_FORMAT_R32G32B32A32_SFLOAT",
                       map.filter == CubeFilter::Linear, "cube map");
  const auto size = static_cast<std::uint32_t>(map.size);
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.flags = VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = kCubeFormat;
  info.extent = {size, size, 1};
  info.mipLevels = 1;
  info.arrayLayers = 6;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  return info;
}

}  // namespace

CubeImage::CubeImage(const VulkanDevice& device, const CubeMap& map, OneTimeCommands& commands,
                     HostBuffer& staging)
    : device_(device),
      image_(device, cubeInfo(device, map), VK_IMAGE_VIEW_TYPE_CUBE, VK_IMAGE_ASPECT_COLOR_BIT) {
  const VkFilter filter = map.filter == CubeFilter::Linear ? VK_FILTER_LINEAR : VK_FILTER_NEAREST;
  sampler_ = makeBaseLevelSampler(device_, filter, VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE);
  try {
    upload(map, commands, staging);
  } catch (...) {
    vkDestroySampler(device_.handle(), sampler_, nullptr);
    throw;
  }
}

CubeImage::~CubeImage() { vkDestroySampler(device_.handle(), sampler_, nullptr); }

void CubeImage::upload(const CubeMap& map, OneTimeCommands& commands, HostBuffer& staging) {
  const auto size = static_cast<std::uint32_t>(map.size);
  const VkDeviceSize faceBytes = VkDeviceSize{size} * size * kTexelBytes;
  staging.reserve(6 * faceBytes);
  VkBufferImageCopy regions[6]{};
  for (std::uint32_t face = 0; face < 6; ++face) {
    // Face data row j becomes image row j: texel (i, j) then means the same
    // to Vulkan's cube addressing as to the CubeMap's own definition.
    std::memcpy(staging.data() + face * faceBytes, map.faces[face].data(), faceBytes);
    regions[face].bufferOffset = face * faceBytes;
    regions[face].imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, face, 1};
    regions[face].imageExtent = {size, size, 1};
  }

  uploadToSampledImage(commands, staging, image_.image(), 6, regions, "cube map upload");
}

}  // namespace snell::vk
