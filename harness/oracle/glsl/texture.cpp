#include "oracle/glsl/texture.h"

#include <cmath>

#include "oracle/reference/cube_sampling.h"
#include "oracle/reference/texture_2d_sampling.h"

namespace snell::glsl {

vec4<double> texture(samplerCube& sampler, const vec3<double>& P) {
  const Direction direction = {P[0], P[1], P[2]};
  const bool zero = direction[0] == 0 && direction[1] == 0 && direction[2] == 0;
  const bool notANumber =
      std::isnan(direction[0]) || std::isnan(direction[1]) || std::isnan(direction[2]);
  if (zero || notANumber) {
    sampler.undefinedLookup = true;
    return splat<double, 4>(0.0);
  }
  // With seamless LINEAR filtering the two faces' footprints meet at the
  // edge with the same texels and weights, so the value is continuous there
  // and a GPU selecting the other face gives nearly the same colour. NEAREST
  // picks a different texel on each side, and non-seamless LINEAR clamps
  // each face to its own edge texels: there the edge is a step.
  const CubeMap& map = *sampler.map;
  if ((map.filter == CubeFilter::Nearest || !map.seamless) && nearCubeFaceEdge(direction))
    sampler.faceEdgeLookup = true;
  const Rgba value = sampleCube(map, direction);
  return vec4<double>(value[0], value[1], value[2], value[3]);
}

vec4<double> texture(sampler2D& sampler, const vec2<double>& P) {
  if (!std::isfinite(P[0]) || !std::isfinite(P[1])) {
    sampler.undefinedLookup = true;
    return splat<double, 4>(0.0);
  }
  const Rgba value = sampleTexture2D(*sampler.image, P[0], P[1]);
  return vec4<double>(value[0], value[1], value[2], value[3]);
}

}  // namespace snell::glsl
