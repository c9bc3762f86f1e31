#pragma once
// 2D textures by the Image they were made from, so that a suite run uploads
// each decal once. As CubeImageCache: an entry is found by the Image's
// address and kept only while a copy of its contents still matches.
#include <cstddef>
#include <memory>
#include <string>

#include "backends/vk/lru_cache.h"
#include "backends/vk/vk_device.h"
#include "backends/vk/vk_host_buffer.h"
#include "backends/vk/vk_one_time_commands.h"
#include "backends/vk/vk_texture_2d.h"
#include "core/image.h"

namespace snell::vk {

class Texture2DCache {
 public:
  // More 2D textures than this in one render is a UsageError: fetching one
  // more could evict an image the same render is about to bind.
  static constexpr std::size_t kCapacity = 16;

  Texture2DCache(const VulkanDevice& device, OneTimeCommands& commands);

  // The texture for `image`, uploaded now unless cached. Throws UsageError,
  // naming `uniform`, for an empty image, one larger than the device takes
  // or one whose pixels do not hold width * height RGBA texels. The
  // reference is valid until the next call.
  const Texture2D& get(const Image& image, const std::string& uniform);

 private:
  struct Entry {
    Image contents;
    std::unique_ptr<Texture2D> texture;
  };

  const VulkanDevice& device_;
  OneTimeCommands& commands_;
  HostBuffer staging_;
  LruCache<Entry> entries_;
};

}  // namespace snell::vk
