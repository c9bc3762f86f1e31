#include "backends/vk/vk_vertex_input.h"

#include <algorithm>
#include <cstring>

namespace snell::vk {

namespace {

VkFormat floatFormat(std::uint32_t components) {
  switch (components) {
    case 1:
      return VK_FORMAT_R32_SFLOAT;
    case 2:
      return VK_FORMAT_R32G32_SFLOAT;
    case 3:
      return VK_FORMAT_R32G32B32_SFLOAT;
    default:
      return VK_FORMAT_R32G32B32A32_SFLOAT;
  }
}

VkDeviceSize alignUp(VkDeviceSize value, VkDeviceSize alignment) {
  return (value + alignment - 1) / alignment * alignment;
}

}  // namespace

VertexInputDescription::VertexInputDescription(const std::vector<VertexInputFormat>& inputs) {
  for (std::uint32_t i = 0; i < inputs.size(); ++i) {
    const VertexInputFormat& input = inputs[i];
    bindings_.push_back(
        {i, input.constant ? 0u : input.components * 4u, VK_VERTEX_INPUT_RATE_VERTEX});
    attributes_.push_back({input.location, i, floatFormat(input.components), 0});
  }
  state_.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO;
  state_.vertexBindingDescriptionCount = static_cast<std::uint32_t>(bindings_.size());
  state_.pVertexBindingDescriptions = bindings_.data();
  state_.vertexAttributeDescriptionCount = static_cast<std::uint32_t>(attributes_.size());
  state_.pVertexAttributeDescriptions = attributes_.data();
}

std::vector<VkDeviceSize> fillVertexBuffer(HostBuffer& buffer,
                                           const std::vector<VertexStream>& streams,
                                           std::uint32_t vertexCount) {
  std::vector<VkDeviceSize> offsets;
  VkDeviceSize bytes = 0;
  for (const VertexStream& stream : streams) {
    offsets.push_back(bytes);
    const VkDeviceSize vertices = stream.constant ? 1 : vertexCount;
    bytes = alignUp(bytes + vertices * stream.components * sizeof(float), 16);
  }
  buffer.reserve(std::max<VkDeviceSize>(bytes, 16));
  for (std::size_t i = 0; i < streams.size(); ++i) {
    const VertexStream& stream = streams[i];
    const std::size_t vertices = stream.constant ? 1 : vertexCount;
    const std::size_t floats = vertices * stream.components;
    const std::size_t given = std::min(floats, stream.data.size());
    std::byte* at = buffer.data() + offsets[i];
    if (given) std::memcpy(at, stream.data.data(), given * sizeof(float));
    std::memset(at + given * sizeof(float), 0, (floats - given) * sizeof(float));
  }
  return offsets;
}

}  // namespace snell::vk
