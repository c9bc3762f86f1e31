#pragma once
// How a program's vertex inputs reach the pipeline, shared by captures and
// renders: one vertex buffer binding per shader input, all streams packed
// into one host buffer.
#include <vulkan/vulkan.h>

#include <compare>
#include <cstdint>
#include <span>
#include <vector>

#include "backends/vk/vk_host_buffer.h"

namespace snell::vk {

struct VertexInputFormat {
  std::uint32_t location = 0;
  std::uint32_t components =
      4;  // fp32 components the stream supplies; Vulkan fills the rest with (0, 0, 1)
  bool constant = false;  // one value for every vertex (stride 0)
  auto operator<=>(const VertexInputFormat&) const = default;
};

struct VertexStream {
  std::span<const float> data;  // `components` floats per vertex; one vertex when constant
  std::uint32_t components = 4;
  bool constant = false;
};

// The pipeline's vertex input state for `inputs`; binding i feeds inputs[i].
class VertexInputDescription {
 public:
  explicit VertexInputDescription(const std::vector<VertexInputFormat>& inputs);
  // Points into this object: keep it alive until the pipeline is created.
  const VkPipelineVertexInputStateCreateInfo& state() const { return state_; }

 private:
  std::vector<VkVertexInputBindingDescription> bindings_;
  std::vector<VkVertexInputAttributeDescription> attributes_;
  VkPipelineVertexInputStateCreateInfo state_{};
};

// Copies the streams into `buffer`, each at its own 16-byte-aligned offset,
// and returns those offsets (binding order). A stream shorter than
// `vertexCount` vertices is padded with zeros. Only call while no submitted
// work uses the buffer.
std::vector<VkDeviceSize> fillVertexBuffer(HostBuffer& buffer,
                                           const std::vector<VertexStream>& streams,
                                           std::uint32_t vertexCount);

}  // namespace snell::vk
