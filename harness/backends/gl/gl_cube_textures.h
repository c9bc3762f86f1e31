#pragma once
#include <cstddef>
#include <cstdint>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_texture_cache.h"
#include "core/cube_map.h"

namespace snell {

// Cube map textures of one context, uploaded once per environment: a suite
// renders many cases against the same CubeMap (see gl_texture_cache.h for
// how an entry is found and trusted). Must be destroyed while its context
// is current.
class GlCubeTextures {
 public:
  // Starts a job: textures bound from here on are kept until it ends.
  void beginJob() { textures_.beginJob(); }

  // Binds `map` to texture unit `unit` (uploading it when needed), with
  // base-level-only sampling, its filter and clamp-to-edge wrapping. The
  // faces must hold size * size * 4 floats each. Leaves `unit` active.
  void bind(const CubeMap& map, int unit);

  std::size_t uploads() const { return uploads_; }  // for tests: how often texels went to GL

 private:
  void upload(const CubeMap& map);  // into the bound texture

  GlTextureCache<CubeMap> textures_;
  std::size_t uploads_ = 0;
};

// A hash of the size and every texel's bits: cheap next to an upload, and it
// sees any change, not just a sample.
std::uint64_t cubeMapHash(const CubeMap& map);

}  // namespace snell
