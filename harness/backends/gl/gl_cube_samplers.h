#pragma once
#include <map>
#include <string>
#include <vector>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_uniform_table.h"
#include "core/cube_map.h"
#include "core/image.h"

namespace snell {

// Which texture feeds each sampler uniform of a program: the samplerCube
// uniforms' cube maps on texture units 0, 1, ..., then the sampler2D
// uniforms' images on the units after them.
struct GlSamplerPlan {
  struct Binding {
    GLint location = -1;
    const CubeMap* map = nullptr;
  };
  struct Binding2D {
    GLint location = -1;
    const Image* image = nullptr;
  };
  std::vector<Binding> bindings;      // cube maps; bindings[k] on unit k
  std::vector<Binding2D> textures2D;  // textures2D[k] on unit bindings.size() + k
  bool seamless = true;  // GL_TEXTURE_CUBE_MAP_SEAMLESS is context state, one value per draw
  int units() const { return static_cast<int>(bindings.size() + textures2D.size()); }
};

// Matches the program's sampler uniforms to the job's cube maps and 2D
// textures before any GL state changes. Throws UsageError, naming the
// uniform, for a sampler the job gives no texture of its kind, one that is
// neither a single samplerCube nor a single sampler2D, a cube map whose
// faces do not hold size * size RGBA texels, an image that does not hold
// width * height RGBA texels, or cube maps that disagree on seamless
// filtering. Textures the program lacks are ignored.
GlSamplerPlan planSamplers(const std::vector<GlUniformTable::Sampler>& samplers,
                           const std::map<std::string, const CubeMap*>& cubeMaps,
                           const std::map<std::string, const Image*>& textures2D);

}  // namespace snell
