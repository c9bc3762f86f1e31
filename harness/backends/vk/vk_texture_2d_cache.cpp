#include "backends/vk/vk_texture_2d_cache.h"

#include <cstdio>
#include <cstring>

#include "core/errors.h"

namespace snell::vk {

namespace {

// Bitwise, so that a NaN texel matches itself.
bool sameContents(const Image& a, const Image& b) {
  return a.width == b.width && a.height == b.height && a.pixels.size() == b.pixels.size() &&
         std::memcmp(a.pixels.data(), b.pixels.data(), a.pixels.size() * sizeof(float)) == 0;
}

void checkWellFormed(const VulkanDevice& device, const Image& image, const std::string& uniform) {
  const std::uint32_t largest = device.limits().maxImageDimension2D;
  const std::string size = std::to_string(image.width) + "x" + std::to_string(image.height);
  if (image.width < 1 || image.height < 1 || static_cast<std::uint32_t>(image.width) > largest ||
      static_cast<std::uint32_t>(image.height) > largest) {
    throw UsageError("2D texture '" + uniform + "' is " + size + "; " +
                     device.driverInfo().renderer + " takes 1 to " + std::to_string(largest) +
                     " texels a side");
  }
  const std::size_t floats = static_cast<std::size_t>(image.width) * image.height * 4;
  if (image.pixels.size() != floats) {
    throw UsageError("2D texture '" + uniform + "' has " + std::to_string(image.pixels.size()) +
                     " floats; " + size + " RGBA needs " + std::to_string(floats));
  }
}

std::string keyOf(const Image& image) {
  char text[32];
  std::snprintf(text, sizeof text, "%p", static_cast<const void*>(&image));
  return text;
}

}  // namespace

Texture2DCache::Texture2DCache(const VulkanDevice& device, OneTimeCommands& commands)
    : device_(device),
      commands_(commands),
      staging_(device, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, 0),
      entries_(kCapacity) {}

const Texture2D& Texture2DCache::get(const Image& image, const std::string& uniform) {
  const std::string key = keyOf(image);
  bool fresh = false;
  Entry& entry = entries_.getOrMake(key, [&] {
    checkWellFormed(device_, image, uniform);
    fresh = true;
    return std::make_unique<Entry>(
        Entry{image, std::make_unique<Texture2D>(device_, image, commands_, staging_)});
  });
  if (fresh || sameContents(entry.contents, image)) return *entry.texture;
  entries_.erase(key);
  return get(image, uniform);
}

}  // namespace snell::vk
