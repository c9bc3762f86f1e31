#include "backends/vk/vk_cube_image_cache.h"

#include <cstdio>
#include <cstring>

#include "core/errors.h"

namespace snell::vk {

namespace {

// Bitwise, so that a NaN texel matches itself.
bool sameContents(const CubeMap& a, const CubeMap& b) {
  if (a.size != b.size || a.filter != b.filter || a.seamless != b.seamless) return false;
  for (int face = 0; face < 6; ++face) {
    const std::vector<float>& x = a.faces[face];
    const std::vector<float>& y = b.faces[face];
    if (x.size() != y.size() || std::memcmp(x.data(), y.data(), x.size() * sizeof(float)) != 0)
      return false;
  }
  return true;
}

void checkWellFormed(const VulkanDevice& device, const CubeMap& map, const std::string& uniform) {
  const std::uint32_t largest = device.limits().maxImageDimensionCube;
  if (map.size < 1 || static_cast<std::uint32_t>(map.size) > largest) {
    throw UsageError("cube map '" + uniform + "' has size " + std::to_string(map.size) + "; " +
                     device.driverInfo().renderer + " takes 1 to " + std::to_string(largest));
  }
  const std::size_t floats = static_cast<std::size_t>(map.size) * map.size * 4;
  for (int face = 0; face < 6; ++face) {
    if (map.faces[face].size() != floats) {
      throw UsageError("cube map '" + uniform + "' face " + std::to_string(face) + " has " +
                       std::to_string(map.faces[face].size()) + " floats; size " +
                       std::to_string(map.size) + " needs " + std::to_string(floats));
    }
  }
  if (!map.seamless) {
    throw UsageError("cube map '" + uniform +
                     "' asks for non-seamless filtering; Vulkan samples cube maps seamlessly");
  }
}

std::string keyOf(const CubeMap& map) {
  char text[32];
  std::snprintf(text, sizeof text, "%p", static_cast<const void*>(&map));
  return text;
}

}  // namespace

CubeImageCache::CubeImageCache(const VulkanDevice& device, OneTimeCommands& commands)
    : device_(device),
      commands_(commands),
      staging_(device, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, 0),
      entries_(kCapacity) {}

const CubeImage& CubeImageCache::get(const CubeMap& map, const std::string& uniform) {
  const std::string key = keyOf(map);
  bool fresh = false;
  Entry& entry = entries_.getOrMake(key, [&] {
    checkWellFormed(device_, map, uniform);
    fresh = true;
    return std::make_unique<Entry>(
        Entry{map, std::make_unique<CubeImage>(device_, map, commands_, staging_)});
  });
  if (fresh || sameContents(entry.contents, map)) return *entry.image;
  entries_.erase(key);
  return get(map, uniform);
}

}  // namespace snell::vk
