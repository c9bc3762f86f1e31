#include "backends/vk/vk_render_target.h"

#include <string>

#include "backends/vk/vk_check.h"
#include "backends/vk/vk_render_pass.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

VkImageCreateInfo attachmentInfo(const VulkanDevice& device, VkFormat format,
                                 VkFormatFeatureFlags features, const char* formatName,
                                 VkImageUsageFlags usage, std::uint32_t width,
                                 std::uint32_t height) {
  VkFormatProperties properties{};
  vkGetPhysicalDeviceFormatProperties(device.physical(), format, &properties);
  if ((properties.optimalTilingFeatures & features) != features) {
    throw SetupError(device.driverInfo().renderer + " cannot render to " + formatName +
                     " images, which snell's float read-back needs");
  }
  VkImageCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO;
  info.imageType = VK_IMAGE_TYPE_2D;
  info.format = format;
  info.extent = {width, height, 1};
  info.mipLevels = 1;
  info.arrayLayers = 1;
  info.samples = VK_SAMPLE_COUNT_1_BIT;
  info.tiling = VK_IMAGE_TILING_OPTIMAL;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  info.initialLayout = VK_IMAGE_LAYOUT_UNDEFINED;
  return info;
}

}  // namespace

RenderTarget::RenderTarget(const VulkanDevice& device, VkRenderPass renderPass,
                           std::uint32_t colourTargets, std::uint32_t width, std::uint32_t height)
    : device_(device),
      depth_(device,
             attachmentInfo(device, kDepthFormat, VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT,
                            "VK_FORMAT_D32_SFLOAT", VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT,
                            width, height),
             VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_DEPTH_BIT) {
  std::vector<VkImageView> views;
  for (std::uint32_t k = 0; k < colourTargets; ++k) {
    colours_.push_back(std::make_unique<DeviceImage>(
        device,
        attachmentInfo(device, kColourFormat,
                       VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_TRANSFER_SRC_BIT,
                       "VK_FORMAT_R32G32B32A32_SFLOAT",
                       VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                       width, height),
        VK_IMAGE_VIEW_TYPE_2D, VK_IMAGE_ASPECT_COLOR_BIT));
    views.push_back(colours_.back()->view());
  }
  views.push_back(depth_.view());
  VkFramebufferCreateInfo info{};
  info.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
  info.renderPass = renderPass;
  info.attachmentCount = static_cast<std::uint32_t>(views.size());
  info.pAttachments = views.data();
  info.width = width;
  info.height = height;
  info.layers = 1;
  check(vkCreateFramebuffer(device_.handle(), &info, nullptr, &framebuffer_),
        "vkCreateFramebuffer");
}

RenderTarget::~RenderTarget() { vkDestroyFramebuffer(device_.handle(), framebuffer_, nullptr); }

}  // namespace snell::vk
