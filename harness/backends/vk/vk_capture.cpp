#include "backends/vk/vk_capture.h"

#include <cstring>

#include "backends/vk/vk_check.h"
#include "core/errors.h"

namespace snell::vk {

CaptureRunner::CaptureRunner(const VulkanDevice& device)
    : device_(device),
      commands_(device),
      uniforms_(device, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, 0),
      vertices_(device, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, 0),
      captured_(device, VK_BUFFER_USAGE_TRANSFORM_FEEDBACK_BUFFER_BIT_EXT,
                VK_MEMORY_PROPERTY_HOST_CACHED_BIT) {
  try {
    const VkDevice handle = device_.handle();
    VkSubpassDescription subpass{};
    subpass.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS;
    VkRenderPassCreateInfo passInfo{};
    passInfo.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO;
    passInfo.subpassCount = 1;
    passInfo.pSubpasses = &subpass;
    check(vkCreateRenderPass(handle, &passInfo, nullptr, &renderPass_), "vkCreateRenderPass");

    VkFramebufferCreateInfo framebufferInfo{};
    framebufferInfo.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO;
    framebufferInfo.renderPass = renderPass_;
    framebufferInfo.width = 1;
    framebufferInfo.height = 1;
    framebufferInfo.layers = 1;
    check(vkCreateFramebuffer(handle, &framebufferInfo, nullptr, &framebuffer_),
          "vkCreateFramebuffer");
  } catch (...) {
    destroy();
    throw;
  }
}

CaptureRunner::~CaptureRunner() { destroy(); }

void CaptureRunner::destroy() {
  const VkDevice handle = device_.handle();
  vkDeviceWaitIdle(handle);
  if (framebuffer_) vkDestroyFramebuffer(handle, framebuffer_, nullptr);
  if (renderPass_) vkDestroyRenderPass(handle, renderPass_, nullptr);
  framebuffer_ = VK_NULL_HANDLE;
  renderPass_ = VK_NULL_HANDLE;
}

std::span<std::byte> CaptureRunner::uniformBlock(std::size_t bytes) {
  uniforms_.reserve(bytes);
  std::memset(uniforms_.data(), 0, bytes);
  return {uniforms_.data(), bytes};
}

std::span<const float> CaptureRunner::run(const CaptureDraw& draw) {
  const VkDeviceSize capturedBytes = VkDeviceSize{draw.vertexCount} * draw.stride;
  if (draw.vertexCount == 0 || draw.vertexCount % 3 != 0 || draw.stride == 0) {
    throw SetupError("capture draw needs a non-zero multiple of 3 vertices and a stride");
  }
  captured_.reserve(capturedBytes);
  // The padding vertices that round the count up to a triangle read zeros.
  const std::vector<VkDeviceSize> offsets =
      fillVertexBuffer(vertices_, draw.streams, draw.vertexCount);
  if (draw.uniformBinding)
    draw.descriptors->writeUniformBuffer(*draw.uniformBinding, uniforms_.handle(),
                                         draw.uniformBytes);

  record(commands_.begin(), draw, offsets);
  commands_.submitAndWait("capture");

  return {reinterpret_cast<const float*>(captured_.data()),
          static_cast<std::size_t>(capturedBytes / sizeof(float))};
}

void CaptureRunner::record(VkCommandBuffer commands, const CaptureDraw& draw,
                           const std::vector<VkDeviceSize>& streamOffsets) {
  VkRenderPassBeginInfo pass{};
  pass.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  pass.renderPass = renderPass_;
  pass.framebuffer = framebuffer_;
  pass.renderArea.extent = {1, 1};
  vkCmdBeginRenderPass(commands, &pass, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.pipeline);
  if (const VkDescriptorSet set = draw.descriptors->set()) {
    vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS,
                            draw.descriptors->pipelineLayout(), 0, 1, &set, 0, nullptr);
  }
  if (!draw.streams.empty()) {
    const std::vector<VkBuffer> buffers(draw.streams.size(), vertices_.handle());
    vkCmdBindVertexBuffers(commands, 0, static_cast<std::uint32_t>(buffers.size()), buffers.data(),
                           streamOffsets.data());
  }
  const TransformFeedbackCommands& xfb = device_.transformFeedback();
  const VkBuffer captured = captured_.handle();
  const VkDeviceSize capturedOffset = 0;
  const VkDeviceSize capturedBytes = VkDeviceSize{draw.vertexCount} * draw.stride;
  xfb.bindBuffers(commands, 0, 1, &captured, &capturedOffset, &capturedBytes);
  xfb.begin(commands, 0, 0, nullptr, nullptr);
  vkCmdDraw(commands, draw.vertexCount, 1, 0, 0);
  xfb.end(commands, 0, 0, nullptr, nullptr);
  vkCmdEndRenderPass(commands);

  VkMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
}

}  // namespace snell::vk
