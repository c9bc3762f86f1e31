#pragma once
// Cube images by the CubeMap they were made from, so that a suite run
// uploads each environment once. An entry is found by the CubeMap's
// address and kept only while a copy of its contents still matches: a map
// changed in place, or a new one at a freed one's address, is uploaded
// afresh rather than served stale.
#include <cstddef>
#include <memory>
#include <string>

#include "backends/vk/lru_cache.h"
#include "backends/vk/vk_cube_image.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"
#include "core/cube_map.h"

namespace snell::vk {

class CubeImageCache {
 public:
  // More cube maps than this in one render is a UsageError: fetching one
  // more could evict an image the same render is about to bind.
  static constexpr std::size_t kCapacity = 16;

  CubeImageCache(const VulkanDevice& device, OneTimeCommands& commands);

  // The image for `map`, uploaded now unless cached. Throws UsageError,
  // naming `uniform`, for a malformed map or one Vulkan cannot sample as
  // asked (non-seamless). The reference is valid until the next call.
  const CubeImage& get(const CubeMap& map, const std::string& uniform);

 private:
  struct Entry {
    CubeMap contents;
    std::unique_ptr<CubeImage> image;
  };

  const VulkanDevice& device_;
  OneTimeCommands& commands_;
  HostBuffer staging_;
  LruCache<Entry> entries_;
};

}  // namespace snell::vk
