#pragma once
#include <map>
#include <string>
#include <vector>

#include "backends/gl/gl_api.h"
#include "backends/gl/gl_uniform_table.h"
#include "core/cube_map.h"

namespace snell {

// Which CubeMap feeds each sampler uniform of a program; sampler i is bound
// to texture unit i.
struct GlCubeSamplerPlan {
  struct Binding {
    GLint location = -1;
    const CubeMap* map = nullptr;
  };
  std::vector<Binding> bindings;
  bool seamless = true;  // GL_TEXTURE_CUBE_MAP_SEAMLESS is context state, one value per draw
};

// Matches the program's sampler uniforms to the job's cube maps before any
// GL state changes. Throws UsageError, naming the uniform, for a sampler
// the job gives no cube map, one that is not a single samplerCube, a cube
// map whose faces do not hold size * size RGBA texels, or cube maps that
// disagree on seamless filtering. Cube maps the program lacks are ignored.
GlCubeSamplerPlan planCubeSamplers(const std::vector<GlUniformTable::Sampler>& samplers,
                                   const std::map<std::string, const CubeMap*>& cubeMaps);

}  // namespace snell
