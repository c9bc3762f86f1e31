#pragma once
// Runs one render: uploads what the draw samples, fills the reusable
// uniform, vertex and index buffers, draws into the target for the
// requested size, copies the colour image into a host buffer, submits and
// waits. Buffers grow as needed and targets are kept per size.
#include <vulkan/vulkan.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "backends/vk/lru_cache.h"
#include "backends/vk/vk_cube_image_cache.h"
#include "backends/vk/vk_descriptor_set.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"
#include "backends/vk/vk_render_pass.h"
#include "backends/vk/vk_render_target.h"
#include "backends/vk/vk_texture_2d_cache.h"
#include "backends/vk/vk_vertex_input.h"
#include "core/cube_map.h"
#include "core/image.h"

namespace snell::vk {

struct CubeMapBinding {
  std::string uniform;  // for messages
  std::uint32_t binding = 0;
  const CubeMap* map = nullptr;
};

struct Texture2DBinding {
  std::string uniform;  // for messages
  std::uint32_t binding = 0;
  const Image* image = nullptr;
};

struct RenderDraw {
  VkPipeline pipeline = VK_NULL_HANDLE;
  const ProgramDescriptorSet* descriptors = nullptr;
  std::optional<std::uint32_t> uniformBinding;  // nullopt when the program has no uniform block
  std::size_t uniformBytes = 0;                 // as written through uniformBlock()
  std::vector<CubeMapBinding> cubeMaps;         // at most CubeImageCache::kCapacity
  std::vector<Texture2DBinding> textures2D;     // at most Texture2DCache::kCapacity
  std::vector<VertexStream> streams;            // in pipeline binding order
  std::uint32_t vertexCount = 0;                // every index is below it
  std::span<const std::uint32_t> indices;       // a triangle list; empty: only clear
  std::uint32_t width = 0;
  std::uint32_t height = 0;
  std::array<float, 4> clearColor{};
  std::uint32_t colourTargets = 1;  // the listing's output, then one per probe
};

class RenderRunner {
 public:
  explicit RenderRunner(const VulkanDevice& device);
  RenderRunner(const RenderRunner&) = delete;
  RenderRunner& operator=(const RenderRunner&) = delete;

  // The pass for this many colour targets, made on first use.
  VkRenderPass renderPass(std::uint32_t colourTargets);

  // Zeroed, mapped room for the next run's uniform block (zero is what GL
  // gives a uniform nobody set).
  std::span<std::byte> uniformBlock(std::size_t bytes);

  // The colour attachments, row 0 at the top, in attachment order.
  std::vector<Image> run(const RenderDraw& draw);

 private:
  void record(VkCommandBuffer commands, const RenderDraw& draw, VkRenderPass renderPass,
              const RenderTarget& target,
              const std::vector<VkDeviceSize>& streamOffsets);

  const VulkanDevice& device_;
  std::map<std::uint32_t, std::unique_ptr<RenderPass>> passes_;
  OneTimeCommands commands_;
  CubeImageCache cubeImages_;
  Texture2DCache textures2D_;
  LruCache<RenderTarget> targets_;
  HostBuffer uniforms_;
  HostBuffer vertices_;
  HostBuffer indices_;
  HostBuffer readBack_;
};

}  // namespace snell::vk
