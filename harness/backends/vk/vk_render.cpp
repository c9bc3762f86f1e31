#include "backends/vk/vk_render.h"

#include <cstring>

#include "core/errors.h"
#include "core/phase_clock.h"

namespace snell::vk {

namespace {

// A suite renders at one or two sizes; a few more cost little to keep.
constexpr std::size_t kCachedTargets = 4;

constexpr VkDeviceSize kPixelBytes = 4 * sizeof(float);

}  // namespace

RenderRunner::RenderRunner(const VulkanDevice& device)
    : device_(device),
      commands_(device),
      cubeImages_(device, commands_),
      textures2D_(device, commands_),
      targets_(kCachedTargets),
      uniforms_(device, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, 0),
      vertices_(device, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT, 0),
      indices_(device, VK_BUFFER_USAGE_INDEX_BUFFER_BIT, 0),
      readBack_(device, VK_BUFFER_USAGE_TRANSFER_DST_BIT, VK_MEMORY_PROPERTY_HOST_CACHED_BIT) {}

std::span<std::byte> RenderRunner::uniformBlock(std::size_t bytes) {
  uniforms_.reserve(bytes);
  std::memset(uniforms_.data(), 0, bytes);
  return {uniforms_.data(), bytes};
}

VkRenderPass RenderRunner::renderPass(std::uint32_t colourTargets) {
  auto& pass = passes_[colourTargets];
  if (!pass) pass = std::make_unique<RenderPass>(device_, colourTargets);
  return pass->handle();
}

std::vector<Image> RenderRunner::run(const RenderDraw& draw) {
  if (draw.cubeMaps.size() > CubeImageCache::kCapacity) {
    throw UsageError("the program samples " + std::to_string(draw.cubeMaps.size()) +
                     " cube maps; a Vulkan render binds at most " +
                     std::to_string(CubeImageCache::kCapacity));
  }
  if (draw.textures2D.size() > Texture2DCache::kCapacity) {
    throw UsageError("the program samples " + std::to_string(draw.textures2D.size()) +
                     " 2D textures; a Vulkan render binds at most " +
                     std::to_string(Texture2DCache::kCapacity));
  }
  if (draw.indices.size() % 3 != 0 || draw.width == 0 || draw.height == 0) {
    throw SetupError("a render needs whole triangles and a non-empty target");
  }
  const PhaseScope phase(Phase::Draw);
  // Uploads submit work of their own, so they come before this draw is recorded.
  for (const CubeMapBinding& cube : draw.cubeMaps) {
    const CubeImage& image = cubeImages_.get(*cube.map, cube.uniform);
    draw.descriptors->writeSampledImage(cube.binding, image.sampler(), image.view());
  }
  for (const Texture2DBinding& bound : draw.textures2D) {
    const Texture2D& texture = textures2D_.get(*bound.image, bound.uniform);
    draw.descriptors->writeSampledImage(bound.binding, texture.sampler(), texture.view());
  }
  if (draw.uniformBinding)
    draw.descriptors->writeUniformBuffer(*draw.uniformBinding, uniforms_.handle(),
                                         draw.uniformBytes);

  const VkRenderPass pass = renderPass(draw.colourTargets);
  const RenderTarget& target =
      targets_.getOrMake(std::to_string(draw.width) + "x" + std::to_string(draw.height) + "x" +
                             std::to_string(draw.colourTargets),
                         [&] {
                           return std::make_unique<RenderTarget>(device_, pass, draw.colourTargets,
                                                                 draw.width, draw.height);
                         });
  std::vector<VkDeviceSize> offsets;
  if (!draw.indices.empty()) {
    offsets = fillVertexBuffer(vertices_, draw.streams, draw.vertexCount);
    indices_.reserve(draw.indices.size_bytes());
    std::memcpy(indices_.data(), draw.indices.data(), draw.indices.size_bytes());
  }
  const VkDeviceSize imageBytes = VkDeviceSize{draw.width} * draw.height * kPixelBytes;
  readBack_.reserve(imageBytes * draw.colourTargets);

  record(commands_.begin(), draw, pass, target, offsets);
  commands_.submitAndWait("render");

  const PhaseScope reading(Phase::ReadBack);
  std::vector<Image> images;
  for (std::uint32_t k = 0; k < draw.colourTargets; ++k) {
    Image image(static_cast<int>(draw.width), static_cast<int>(draw.height));
    std::memcpy(image.pixels.data(), readBack_.data() + k * imageBytes, imageBytes);
    images.push_back(std::move(image));
  }
  return images;
}

void RenderRunner::record(VkCommandBuffer commands, const RenderDraw& draw, VkRenderPass renderPass,
                          const RenderTarget& target,
                          const std::vector<VkDeviceSize>& streamOffsets) {
  // The listing's target is cleared to the job's colour, each probe's to 0:
  // alpha 0 marks a pixel its write never reached.
  std::vector<VkClearValue> clears(draw.colourTargets + 1);
  for (int c = 0; c < 4; ++c) clears[0].color.float32[c] = draw.clearColor[c];
  clears.back().depthStencil = {1.0f, 0};
  VkRenderPassBeginInfo pass{};
  pass.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO;
  pass.renderPass = renderPass;
  pass.framebuffer = target.framebuffer();
  pass.renderArea.extent = {draw.width, draw.height};
  pass.clearValueCount = static_cast<std::uint32_t>(clears.size());
  pass.pClearValues = clears.data();
  vkCmdBeginRenderPass(commands, &pass, VK_SUBPASS_CONTENTS_INLINE);

  if (!draw.indices.empty()) {
    vkCmdBindPipeline(commands, VK_PIPELINE_BIND_POINT_GRAPHICS, draw.pipeline);
    // A negative height (core since Vulkan 1.1) starts the viewport at the
    // bottom row and runs it upwards, so clip-space +y is up as in OpenGL
    // and framebuffer row 0, the first row copied out, is the image's top.
    const auto width = static_cast<float>(draw.width);
    const auto height = static_cast<float>(draw.height);
    const VkViewport viewport{0.0f, height, width, -height, 0.0f, 1.0f};
    vkCmdSetViewport(commands, 0, 1, &viewport);
    const VkRect2D scissor{{0, 0}, {draw.width, draw.height}};
    vkCmdSetScissor(commands, 0, 1, &scissor);
    if (const VkDescriptorSet set = draw.descriptors->set()) {
      vkCmdBindDescriptorSets(commands, VK_PIPELINE_BIND_POINT_GRAPHICS,
                              draw.descriptors->pipelineLayout(), 0, 1, &set, 0, nullptr);
    }
    if (!draw.streams.empty()) {
      const std::vector<VkBuffer> buffers(draw.streams.size(), vertices_.handle());
      vkCmdBindVertexBuffers(commands, 0, static_cast<std::uint32_t>(buffers.size()),
                             buffers.data(), streamOffsets.data());
    }
    vkCmdBindIndexBuffer(commands, indices_.handle(), 0, VK_INDEX_TYPE_UINT32);
    vkCmdDrawIndexed(commands, static_cast<std::uint32_t>(draw.indices.size()), 1, 0, 0, 0);
  }
  vkCmdEndRenderPass(commands);

  // The pass leaves the colour image in TRANSFER_SRC_OPTIMAL, after its writes.
  for (std::uint32_t k = 0; k < draw.colourTargets; ++k) {
    VkBufferImageCopy region{};
    region.bufferOffset = VkDeviceSize{k} * draw.width * draw.height * kPixelBytes;
    region.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1};
    region.imageExtent = {draw.width, draw.height, 1};
    vkCmdCopyImageToBuffer(commands, target.colourImage(k), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL,
                           readBack_.handle(), 1, &region);
  }
  VkMemoryBarrier toHost{};
  toHost.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER;
  toHost.srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT;
  toHost.dstAccessMask = VK_ACCESS_HOST_READ_BIT;
  vkCmdPipelineBarrier(commands, VK_PIPELINE_STAGE_TRANSFER_BIT, VK_PIPELINE_STAGE_HOST_BIT, 0, 1,
                       &toHost, 0, nullptr, 0, nullptr);
}

}  // namespace snell::vk
