#pragma once
// An environment cube map as data: six square RGBA32F faces, base level
// only (scenes use no mipmaps). Face order and texel addressing follow the
// GL/Vulkan cube map rules: faces +X, -X, +Y, -Y, +Z, -Z; in each face,
// texel (i, j) covers s in [i/size, (i+1)/size] and t in [j/size,
// (j+1)/size], stored at faces[f][(j * size + i) * 4]. Backends upload row
// j as the face image's row j, so texel (i, j) means the same on both APIs
// and in the CPU sampler.
#include <array>
#include <vector>

namespace snell {

enum class CubeFilter { Nearest, Linear };

struct CubeMap {
  int size = 0;
  std::array<std::vector<float>, 6> faces;  // size * size * 4 floats each
  CubeFilter filter = CubeFilter::Linear;
  bool seamless = true;  // Vulkan always; OpenGL enables GL_TEXTURE_CUBE_MAP_SEAMLESS
};

}  // namespace snell
