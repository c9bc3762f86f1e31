#pragma once
#include <cstddef>
#include <cstdint>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_texture_cache.h"
#include "core/image.h"

namespace snell {

// 2D textures of one context, uploaded once per image, as GlCubeTextures
// keeps cube maps (gl_texture_cache.h). Must be destroyed while its context
// is current.
class GlTextures2D {
 public:
  // Starts a job: textures bound from here on are kept until it ends.
  void beginJob() { textures_.beginJob(); }

  // Binds `image` to texture unit `unit` (uploading it when needed) as
  // RGBA32F, base level only, LINEAR filtering and REPEAT wrapping (what
  // RenderJob::textures2D promises). Row j of the image is row j of the
  // texture. The image must hold width * height * 4 floats. Leaves `unit`
  // active.
  void bind(const Image& image, int unit);

  std::size_t uploads() const { return uploads_; }  // for tests: how often texels went to GL

 private:
  void upload(const Image& image);  // into the bound texture

  GlTextureCache<Image> textures_;
  std::size_t uploads_ = 0;
};

// A hash of the size and every texel's bits.
std::uint64_t imageHash(const Image& image);

}  // namespace snell
