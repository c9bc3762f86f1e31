#include "backends/gl/gl_textures_2d.h"

#include <array>
#include <cstring>

#include "backends/gl/gl_error_check.h"

namespace snell {

std::uint64_t imageHash(const Image& image) {
  // Four independent lanes, as cubeMapHash: the multiplies overlap.
  constexpr std::uint64_t kPrime = 0x100000001b3ull;
  std::array<std::uint64_t, 4> lanes{0xcbf29ce484222325ull, 0x84222325cbf29ce4ull,
                                     0x9e3779b97f4a7c15ull, 0xbf58476d1ce4e5b9ull};
  lanes[0] ^= static_cast<std::uint64_t>(image.width);
  lanes[1] ^= static_cast<std::uint64_t>(image.height);
  lanes[2] ^= image.pixels.size();
  const std::size_t count = image.pixels.size();
  std::size_t i = 0;
  for (; i + 4 <= count; i += 4) {
    for (std::size_t lane = 0; lane < 4; ++lane) {
      std::uint32_t bits;
      std::memcpy(&bits, &image.pixels[i + lane], sizeof bits);
      lanes[lane] = (lanes[lane] ^ bits) * kPrime;
    }
  }
  for (; i < count; ++i) {
    std::uint32_t bits;
    std::memcpy(&bits, &image.pixels[i], sizeof bits);
    lanes[0] = (lanes[0] ^ bits) * kPrime;
  }
  std::uint64_t hash = 0;
  for (std::uint64_t lane : lanes) hash = (hash ^ lane) * kPrime + (hash >> 29);
  return hash;
}

GlTextures2D::~GlTextures2D() {
  for (auto& [image, texture] : textures_) glDeleteTextures(1, &texture.id);
}

void GlTextures2D::bind(const Image& image, int unit) {
  Texture& texture = entryFor(image);
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture.id);
  const std::uint64_t hash = imageHash(image);
  if (texture.width != image.width || texture.height != image.height || texture.hash != hash) {
    texture.width = 0;  // an upload that fails part way must not pass for the old content
    upload(image);
    texture.width = image.width;
    texture.height = image.height;
    texture.hash = hash;
  }
  texture.lastJob = job_;
}

GlTextures2D::Texture& GlTextures2D::entryFor(const Image& image) {
  const auto found = textures_.find(&image);
  if (found != textures_.end()) return found->second;
  if (textures_.size() >= kCapacity) evictOneUnusedThisJob();
  Texture texture;
  glGenTextures(1, &texture.id);
  throwOnGlError("glGenTextures");
  return textures_.emplace(&image, texture).first->second;
}

void GlTextures2D::evictOneUnusedThisJob() {
  auto oldest = textures_.end();
  for (auto entry = textures_.begin(); entry != textures_.end(); ++entry) {
    if (entry->second.lastJob == job_) continue;
    if (oldest == textures_.end() || entry->second.lastJob < oldest->second.lastJob) oldest = entry;
  }
  if (oldest == textures_.end()) return;  // every texture serves this job
  glDeleteTextures(1, &oldest->second.id);
  textures_.erase(oldest);
}

void GlTextures2D::upload(const Image& image) {
  // Base level only: with no other level the texture is complete without
  // mipmaps, and the LINEAR minification filter samples that level.
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, GL_LINEAR);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, GL_REPEAT);
  glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, GL_REPEAT);
  // Image rows are tightly packed float RGBA: 4-byte alignment holds, and
  // no earlier client state may skip or stride them.
  glPixelStorei(GL_UNPACK_ALIGNMENT, 4);
  glPixelStorei(GL_UNPACK_ROW_LENGTH, 0);
  glPixelStorei(GL_UNPACK_SKIP_ROWS, 0);
  glPixelStorei(GL_UNPACK_SKIP_PIXELS, 0);
  // Row j of the image (image.at(i, j)) becomes row j of the texture, t in
  // [j/height, (j+1)/height]: no flip.
  glTexImage2D(GL_TEXTURE_2D, 0, GL_RGBA32F, image.width, image.height, 0, GL_RGBA, GL_FLOAT,
               image.pixels.data());
  throwOnGlError("glTexImage2D(GL_TEXTURE_2D, GL_RGBA32F)");
  ++uploads_;
}

}  // namespace snell
