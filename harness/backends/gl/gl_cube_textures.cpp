#include "backends/gl/gl_cube_textures.h"

#include <array>
#include <cstring>

#include "backends/gl/gl_error_check.h"

namespace snell {

std::uint64_t cubeMapHash(const CubeMap& map) {
  // Four independent lanes so that the multiplies overlap instead of
  // waiting on each other; the faces of a 512 environment are 25 MB.
  constexpr std::uint64_t kPrime = 0x100000001b3ull;
  std::array<std::uint64_t, 4> lanes{0xcbf29ce484222325ull, 0x84222325cbf29ce4ull,
                                     0x9e3779b97f4a7c15ull, 0xbf58476d1ce4e5b9ull};
  lanes[0] ^= static_cast<std::uint64_t>(map.size);
  for (const std::vector<float>& face : map.faces) {
    const std::size_t count = face.size();
    lanes[1] ^= count;
    std::size_t i = 0;
    for (; i + 4 <= count; i += 4) {
      for (std::size_t lane = 0; lane < 4; ++lane) {
        std::uint32_t bits;
        std::memcpy(&bits, &face[i + lane], sizeof bits);
        lanes[lane] = (lanes[lane] ^ bits) * kPrime;
      }
    }
    for (; i < count; ++i) {
      std::uint32_t bits;
      std::memcpy(&bits, &face[i], sizeof bits);
      lanes[0] = (lanes[0] ^ bits) * kPrime;
    }
  }
  std::uint64_t hash = 0;
  for (std::uint64_t lane : lanes) hash = (hash ^ lane) * kPrime + (hash >> 29);
  return hash;
}

GlCubeTextures::~GlCubeTextures() {
  for (auto& [map, texture] : textures_) glDeleteTextures(1, &texture.id);
}

void GlCubeTextures::bind(const CubeMap& map, int unit) {
  Texture& texture = entryFor(map);
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture.id);
  const std::uint64_t hash = cubeMapHash(map);
  if (texture.size != map.size || texture.hash != hash) {
    texture.size = 0;  // an upload that fails part way must not pass for the old content
    upload(map);
    texture.size = map.size;
    texture.hash = hash;
  }
  // The filter is sampling state, not content: the same texels may be
  // sampled either way by different jobs.
  const GLint filter = map.filter == CubeFilter::Nearest ? GL_NEAREST : GL_LINEAR;
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, filter);
  texture.lastJob = job_;
  throwOnGlError("binding a cube map texture (glBindTexture, glTexParameteri)");
}

GlCubeTextures::Texture& GlCubeTextures::entryFor(const CubeMap& map) {
  const auto found = textures_.find(&map);
  if (found != textures_.end()) return found->second;
  if (textures_.size() >= kCapacity) evictOneUnusedThisJob();
  Texture texture;
  glGenTextures(1, &texture.id);
  throwOnGlError("glGenTextures");
  return textures_.emplace(&map, texture).first->second;
}

void GlCubeTextures::evictOneUnusedThisJob() {
  auto oldest = textures_.end();
  for (auto entry = textures_.begin(); entry != textures_.end(); ++entry) {
    if (entry->second.lastJob == job_) continue;
    if (oldest == textures_.end() || entry->second.lastJob < oldest->second.lastJob) oldest = entry;
  }
  if (oldest == textures_.end()) return;  // every texture serves this job
  glDeleteTextures(1, &oldest->second.id);
  textures_.erase(oldest);
}

void GlCubeTextures::upload(const CubeMap& map) {
  // Scenes sample the base level only; with no other level the texture is
  // complete without mipmaps.
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BASE_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAX_LEVEL, 0);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_WRAP_R, GL_CLAMP_TO_EDGE);
  for (int face = 0; face < 6; ++face) {
    // Row j of the face data is row j of the face image (t in [j/size,
    // (j+1)/size]), as cube_map.h lays it out: no flip.
    glTexImage2D(static_cast<GLenum>(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), 0, GL_RGBA32F,
                 map.size, map.size, 0, GL_RGBA, GL_FLOAT, map.faces[static_cast<std::size_t>(face)].data());
  }
  throwOnGlError("glTexImage2D(GL_TEXTURE_CUBE_MAP_*, GL_RGBA32F)");
  ++uploads_;
}

}  // namespace snell
