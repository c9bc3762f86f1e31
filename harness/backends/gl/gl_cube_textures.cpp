#include "backends/gl/gl_cube_textures.h"

#include "backends/gl/gl_error_check.h"

namespace snell {

std::uint64_t cubeMapHash(const CubeMap& map) {
  TexelHash hash;
  hash.mix(static_cast<std::uint64_t>(map.size));
  for (const std::vector<float>& face : map.faces) hash.mix(face);
  return hash.value();
}

void GlCubeTextures::bind(const CubeMap& map, int unit) {
  GlTextureCache<CubeMap>::Entry& texture = textures_.entryFor(map);
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_CUBE_MAP, texture.id);
  const std::uint64_t hash = cubeMapHash(map);
  if (!texture.uploaded || texture.hash != hash) {
    texture.uploaded = false;  // an upload that fails part way must not pass for the old content
    upload(map);
    texture.uploaded = true;
    texture.hash = hash;
  }
  // The filter is sampling state, not content: the same texels may be
  // sampled either way by different jobs.
  const GLint filter = map.filter == CubeFilter::Nearest ? GL_NEAREST : GL_LINEAR;
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER, filter);
  glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER, filter);
  throwOnGlError("binding a cube map texture (glBindTexture, glTexParameteri)");
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
                 map.size, map.size, 0, GL_RGBA, GL_FLOAT,
                 map.faces[static_cast<std::size_t>(face)].data());
  }
  throwOnGlError("glTexImage2D(GL_TEXTURE_CUBE_MAP_*, GL_RGBA32F)");
  ++uploads_;
}

}  // namespace snell
