#include "backends/gl/gl_textures_2d.h"

#include "backends/gl/gl_error_check.h"

namespace snell {

std::uint64_t imageHash(const Image& image) {
  TexelHash hash;
  hash.mix(static_cast<std::uint64_t>(image.width));
  hash.mix(static_cast<std::uint64_t>(image.height));
  hash.mix(image.pixels);
  return hash.value();
}

void GlTextures2D::bind(const Image& image, int unit) {
  GlTextureCache<Image>::Entry& texture = textures_.entryFor(image);
  glActiveTexture(static_cast<GLenum>(GL_TEXTURE0 + unit));
  glBindTexture(GL_TEXTURE_2D, texture.id);
  const std::uint64_t hash = imageHash(image);
  if (!texture.uploaded || texture.hash != hash) {
    texture.uploaded = false;  // an upload that fails part way must not pass for the old content
    upload(image);
    texture.uploaded = true;
    texture.hash = hash;
  }
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
