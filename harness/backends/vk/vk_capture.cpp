#include "backends/vk/vk_capture.h"

#include <algorithm>
#include <cstring>

#include "backends/vk/vk_check.h"
#include "core/errors.h"

namespace snell::vk {

namespace {

// llvmpipe JITs a new pipeline on its first draw (~0.1 s); a minute means a hang.
constexpr std::uint64_t kFenceTimeoutNs = 60ull * 1000 * 1000 * 1000;

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace

CaptureRunner::CaptureRunner(const VulkanDevice& device)
    : device_(device),
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

    VkCommandPoolCreateInfo poolInfo{};
    poolInfo.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO;
    poolInfo.flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT;
    poolInfo.queueFamilyIndex = device_.queueFamily();
    check(vkCreateCommandPool(handle, &poolInfo, nullptr, &pool_), "vkCreateCommandPool");
    VkCommandBufferAllocateInfo allocation{};
    allocation.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO;
    allocation.commandPool = pool_;
    allocation.level = VK_COMMAND_BUFFER_LEVEL_PRIMARY;
    allocation.commandBufferCount = 1;
    check(vkAllocateCommandBuffers(handle, &allocation, &commands_), "vkAllocateCommandBuffers");

    VkFenceCreateInfo fenceInfo{};
    fenceInfo.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO;
    check(vkCreateFence(handle, &fenceInfo, nullptr, &fence_), "vkCreateFence");
  } catch (...) {
    destroy();
    throw;
  }
}

CaptureRunner::~CaptureRunner() { destroy(); }

void CaptureRunner::destroy() {
  const VkDevice handle = device_.handle();
  vkDeviceWaitIdle(handle);
  if (fence_) vkDestroyFence(handle, fence_, nullptr);
  if (pool_) vkDestroyCommandPool(handle, pool_, nullptr);
  if (framebuffer_) vkDestroyFramebuffer(handle, framebuffer_, nullptr);
  if (renderPass_) vkDestroyRenderPass(handle, renderPass_, nullptr);
  fence_ = VK_NULL_HANDLE;
  pool_ = VK_NULL_HANDLE;
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

  // Streams share one buffer, each at its own 16-byte-aligned offset.
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize vertexBytes = 0;
  for (const VertexStream& stream : draw.streams) {
    offsets.push_back(vertexBytes);
    const VkDeviceSize vertices = stream.constant ? 1 : draw.vertexCount;
    vertexBytes = alignUp(vertexBytes + vertices * stream.components * sizeof(float), 16);
  }
  vertices_.reserve(std::max<VkDeviceSize>(vertexBytes, 16));
  for (std::size_t i = 0; i < draw.streams.size(); ++i) {
    const VertexStream& stream = draw.streams[i];
    const std::size_t vertices = stream.constant ? 1 : draw.vertexCount;
    const std::size_t floats = vertices * stream.components;
    const std::size_t given = std::min(floats, stream.data.size());
    std::byte* at = vertices_.data() + offsets[i];
    std::memcpy(at, stream.data.data(), given * sizeof(float));
    // The padding vertices that round the count up to a triangle read zeros.
    std::memset(at + given * sizeof(float), 0, (floats - given) * sizeof(float));
  }

  if (draw.descriptorSet) {
    VkDescriptorBufferInfo bufferInfo{uniforms_.handle(), 0, draw.uniformBytes};
    VkWriteDescriptorSet write{};
    write.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET;
    write.dstSet = draw.descriptorSet;
    write.dstBinding = draw.uniformBinding;
    write.descriptorCount = 1;
    write.descriptorType = VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    write.pBufferInfo = &bufferInfo;
    vkUpdateDescriptorSets(device_.handle(), 1, &write, 0, nullptr);
  }

  record(draw, offsets);

  VkSubmitInfo submit{};
  submit.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO;
  submit.commandBufferCount = 1;
  submit.pCommandBuffers = &commands_;
  check(vkQueueSubmit(device_.queue(), 1, &submit, fence_), "vkQueueSubmit");
  const VkResult waited = vkWaitForFences(device_.handle(), 1, &fence_, VK_TRUE, kFenceTimeoutNs);
  if (waited == VK_TIMEOUT) throw SetupError("the Vulkan capture did not finish within 60 s");
  check(waited, "vkWaitForFences");
  check(vkResetFences(device_.handle(), 1, &fence_), "vkResetFences");

  return {reinterpret_cast<const float*>(captured_.data()),
          static_cast<std::size_t>(capturedBytes / sizeof(float))};
}

void CaptureRunner::record(const CaptureDraw& draw,
                           const std::vector<VkDeviceSize>& streamOffsets) {
  check(vkResetCommandBuffer(commands_, 0), "vkResetCommandBuffer");
  VkCommandBufferBeginInfo begin{};
  begin.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO;
  begin.flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT;
  check(vkBeginCommandBuffer(commands_, &begin), "vkBeginCommandBuffer");

  VkRenderPassBeginInfo pass{};
  pass.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  pass.renderPass = renderPass_;
  pass.framebuffer = framebuffer_;
  pass.renderArea.extent = {1, 1};
  vkCmdBeginRenderPass(commands_, &pass, VK_SUBPASS_CONTENTS_INLINE);
  vkCmdBindPipeline(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.pipeline);
  if (draw.descriptorSet) {
    vkCmdBindDescriptorSets(commands_, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.layout, 0, 1,
                            &draw.descriptorSet, 0, nullptr);
  }
  if (!draw.streams.empty()) {
    const std::vector<VkBuffer> buffers(draw.streams.size(), vertices_.handle());
    vkCmdBindVertexBuffers(commands_, 0, static_cast<std::uint32_t>(buffers.size()), buffers.data(),
                           streamOffsets.data());
  }
  const TransformFeedbackCommands& xfb = device_.transformFeedback();
  const VkBuffer captured = captured_.handle();
  const VkDeviceSize capturedOffset = 0;
  const VkDeviceSize capturedBytes = VkDeviceSize{draw.vertexCount} * draw.stride;
  xfb.bindBuffers(commands_, 0, 1, &captured, &capturedOffset, &capturedBytes);
  xfb.begin(commands_, 0, 0, nullptr, nullptr);
  vkCmdDraw(commands_, draw.vertexCount, 1, 0, 0);
  xfb.end(commands_, 0, 0, nullptr, nullptr);
  vkCmdEndRenderPass(commands_);

  VkMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_TRANSFORM_FEEDBACK_WRITE_BIT_EXT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands_, VK_PIPELINE_STAGE_TRANSFORM_FEEDBACK_BIT_EXT,
                       VK_PIPELINE_STAGE_HOST_BIT, 0, 1, &toHost, 0, nullptr, 0, nullptr);
  check(vkEndCommandBuffer(commands_), "vkEndCommandBuffer");
}

}  // namespace snell::vk
