#pragma once
// Runs one transform feedback capture: fills the reusable uniform, vertex
// and capture buffers, records a draw with rasterization discarded, submits
// it and waits. Every buffer grows as needed and is kept for the next call.
#include <vulkan/vulkan.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "backends/vk/vk_descriptor_set.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"
#include "backends/vk/vk_vertex_input.h"

namespace snell::vk {

struct CaptureDraw {
  VkPipeline pipeline = VK_NULL_HANDLE;
  const ProgramDescriptorSet* descriptors = nullptr;
  std::optional<std::uint32_t> uniformBinding;  // nullopt when the shader has no uniform block
  std::size_t uniformBytes = 0;                 // as written through uniformBlock()
  std::vector<VertexStream> streams;            // in pipeline binding order
  std::uint32_t vertexCount = 0;                // a multiple of 3: the pipeline draws triangles
  std::uint32_t stride = 0;                     // bytes per vertex in transform feedback buffer 0
};

class CaptureRunner {
 public:
  explicit CaptureRunner(const VulkanDevice& device);
  ~CaptureRunner();
  CaptureRunner(const CaptureRunner&) = delete;
  CaptureRunner& operator=(const CaptureRunner&) = delete;

  // The pass every capture pipeline is built against: no attachments at all.
  VkRenderPass renderPass() const { return renderPass_; }

  // Zeroed, mapped room for the next run's uniform block (zero is what GL
  // gives a uniform nobody set).
  std::span<std::byte> uniformBlock(std::size_t bytes);

  // The captured records (stride / 4 floats per vertex), valid until the next run.
  std::span<const float> run(const CaptureDraw& draw);

 private:
  void destroy();
  void record(VkCommandBuffer commands, const CaptureDraw& draw,
              const std::vector<VkDeviceSize>& streamOffsets);

  const VulkanDevice& device_;
  VkRenderPass renderPass_ = VK_NULL_HANDLE;
  VkFramebuffer framebuffer_ = VK_NULL_HANDLE;
  OneTimeCommands commands_;
  HostBuffer uniforms_;
  HostBuffer vertices_;
  HostBuffer captured_;
};

}  // namespace snell::vk
