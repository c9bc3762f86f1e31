#pragma once
// The CPU reference image of a drawing listing: the same triangles
// rasterised on the CPU with perspective-correct interpolation of the
// listing's vertex outputs (from its vertex oracle, in double), then the
// listing's fragment part evaluated per pixel with cube maps and 2D textures
// sampled as the GL/Vulkan specs define. No graphics API in here.
#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "core/cube_map.h"
#include "core/image.h"
#include "core/pixel_mask.h"
#include "core/values.h"

namespace snell {

struct ReferenceImage {
  Image color;                  // the reference colour, linear float
  std::vector<PixelMask> mask;  // width * height, row 0 at the top
  std::size_t count(PixelMask m) const;
};

class VertexOracle;
class FragmentOracle;

struct ReferenceInput {
  std::string oracle;  // names the listing's parts in messages, and finds them when not given below
  const UniformMap& uniforms;
  const ConstantMap& constants;
  const AttributeMap& attributes;
  std::size_t vertexCount = 0;
  const std::vector<std::uint32_t>& indices;       // triangle list, counter-clockwise front faces
  std::map<std::string, const CubeMap*> cubeMaps;  // samplerCube uniforms by GLSL name
  int width = 256;
  int height = 256;
  std::array<float, 4> clearColor{0, 0, 0, 0};
  bool cullBackFaces = true;
  // sampler2D uniforms by GLSL name, sampled as RenderJob::textures2D says.
  std::map<std::string, const Image*> textures2D{};
  // The listing's parts (a derived oracle's, harness/derived); null: the
  // parts registered under `oracle`.
  const VertexOracle* vertex = nullptr;
  const FragmentOracle* fragment = nullptr;
};

// Whether the listing named by `oracle` has a fragment part (it draws).
bool hasFragmentOracle(const std::string& oracle);

// Throws UsageError when the oracle has no fragment part or an input is missing.
ReferenceImage renderReferenceImage(const ReferenceInput& input);

}  // namespace snell
